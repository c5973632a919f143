package handsim.control;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.Home;
import handsim.config.Json;
import handsim.kin.Frame;
import handsim.kin.Kinematics;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.Dof;
import handsim.model.HandModel;
import handsim.model.Site;
import handsim.task.FlipTask;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** Damped least squares IK (eq. 2) on the shipped model, with the shipped IK settings. */
@Tag("fast")
class DlsIkTest {

    /** Reachable palm targets are reached within 1 mm and 1 degree. */
    static final double POSITION_TOLERANCE = 1e-3;
    static final double ROTATION_TOLERANCE = Math.toRadians(1);
    /** Enough iterations for the damped steps to converge from neutral (the controller warm-starts 2 per tick). */
    static final int ITERATIONS = 400;

    private final HandModel model = TestSupport.model();
    private final Kinematics kin = new Kinematics(model);
    private final Site palm = model.site("palm_center");
    private final DlsIk ik = new DlsIk(kin, palm,
            ControllerConfig.load(Home.resolve("configs/controller.json")).ik());

    @Test
    void reachesReachablePalmTargetsWithin1mmAnd1Degree() {
        // targets made by forward kinematics of arm poses inside the limits are reachable by construction
        SplittableRandom rng = new SplittableRandom(7);
        double[] neutral = model.poseVector("neutral");
        for (int trial = 0; trial < 20; trial++) {
            double[] goal = neutral.clone();
            for (int d : ik.dofs()) {
                Dof dof = model.dofs().get(d);
                goal[d] = dof.clamp(goal[d] + 0.5 * (2 * rng.nextDouble() - 1));
            }
            Frame target = kin.siteFrame(palm, goal);
            double[] q = neutral.clone();
            DlsIk.Residual r = ik.solve(q, target, ITERATIONS);
            assertTrue(r.position() < POSITION_TOLERANCE, "trial " + trial + ": position error " + r.position() + " m");
            assertTrue(r.rotation() < ROTATION_TOLERANCE,
                    "trial " + trial + ": rotation error " + Math.toDegrees(r.rotation()) + " deg");
            assertInsideLimits(q);
        }
    }

    @Test
    void drawingTheArmTowardAPostureTurnsItsRedundancyAndLeavesThePalmWhereItIs() {
        // GOBACK's ticks with the palm held at rest: solve (2 iterations), then one pull toward the can's arm rest
        // (configs/tasks/flip.json), from the neutral pose, whose redundancy is far from it (21 deg of shoulder abduction)
        ArmRest rest = FlipTask.Config.parse(Json.load(Home.resolve("configs/tasks/flip.json"))).objects().get("can").armRest()
                .orElseThrow();
        double[] posture = rest.chainVector(model, ik.dofs());
        double[] q = model.poseVector("neutral");
        Frame atRest = kin.siteFrame(palm, q);
        double start = chainDistance(q, posture);
        for (int tick = 0; tick < 1000; tick++) {
            ik.solve(q, atRest);
            ik.pullNullSpace(q, posture, rest.gain());
            Frame now = kin.siteFrame(palm, q);
            // the pull moves the palm only to second order (and by the damping's leak), and the next solve takes it back
            assertTrue(now.origin().distance(atRest.origin()) < POSITION_TOLERANCE, "tick " + tick + ": palm moved "
                    + now.origin().distance(atRest.origin()) + " m");
            assertTrue(now.rotation().angleTo(atRest.rotation()) < ROTATION_TOLERANCE, "tick " + tick + ": palm turned "
                    + Math.toDegrees(now.rotation().angleTo(atRest.rotation())) + " deg");
            assertInsideLimits(q);
        }
        // the posture's own palm lies within millimetres of the neutral one (it was measured at throw decisions, the
        // palm held there by PD), so the chain comes close to it, not onto it: a fifth of the way left at most
        double end = chainDistance(q, posture);
        assertTrue(end < 0.2 * start, "distance to the posture " + start + " -> " + end + " rad");
    }

    @Test
    void aPostureTheArmAlreadyHasIsNoPull() {
        double[] q = model.poseVector("neutral");
        double[] posture = new double[ik.dofs().length];
        for (int c = 0; c < posture.length; c++) {
            posture[c] = q[ik.dofs()[c]];
        }
        double[] pulled = q.clone();
        ik.pullNullSpace(pulled, posture, 0.5);
        assertArrayEquals(q, pulled, 1e-15);
    }

    private double chainDistance(double[] q, double[] posture) {
        double sum = 0;
        for (int c = 0; c < posture.length; c++) {
            double d = q[ik.dofs()[c]] - posture[c];
            sum += d * d;
        }
        return Math.sqrt(sum);
    }

    @Test
    void staysInsideJointLimitsForUnreachableTargets() {
        // 2 m from the shoulder, or behind the back with the palm turned over: out of the arm's reach
        Vec3 shoulder = model.joints().get(0).anchor();
        Frame[] targets = {
            new Frame(shoulder.plus(new Vec3(0.3, 0.5, 2.0)), Quat.IDENTITY),
            new Frame(shoulder.plus(new Vec3(-0.2, -0.3, -0.5)), Quat.fromAxisAngle(Vec3.X, Math.PI)),
            new Frame(shoulder.plus(new Vec3(0, 1.5, 0)), Quat.fromAxisAngle(Vec3.Z, 2.5)),
        };
        for (Frame target : targets) {
            double[] q = model.poseVector("neutral");
            DlsIk.Residual r = ik.solve(q, target, ITERATIONS);
            assertInsideLimits(q);
            assertTrue(Double.isFinite(r.position()) && r.position() > 0.1, "target should stay out of reach: " + r);
        }
    }

    private void assertInsideLimits(double[] q) {
        for (int d : ik.dofs()) {
            Dof dof = model.dofs().get(d);
            assertTrue(q[d] >= dof.lower() - 1e-12 && q[d] <= dof.upper() + 1e-12,
                    dof.name() + " = " + Math.toDegrees(q[d]) + " deg outside its range");
        }
    }
}
