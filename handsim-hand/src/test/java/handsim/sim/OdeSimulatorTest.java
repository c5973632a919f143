package handsim.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.kin.Frame;
import handsim.kin.Kinematics;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.model.Site;
import handsim.sim.ode.IsolatedEngine;
import handsim.sim.ode.OdeSimulator;
import handsim.task.HeldBallScenario;
import handsim.task.ServoLoop;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** Small simulations with expectations derived from the model and the contact law. */
@Tag("slow")
class OdeSimulatorTest {

    private final HandModel m = TestSupport.model();
    private final SimConfig config = TestSupport.simConfig();

    private static int steps(SimConfig c, double seconds) {
        return (int) Math.round(seconds / c.timeStep());
    }

    @Test
    void engineJointStateEqualsTheKinematicsAfterReset() {
        SplittableRandom rng = new SplittableRandom(11);
        try (OdeSimulator sim = new OdeSimulator(m, config)) {
            double[] q = new double[m.dofCount()], qd = new double[m.dofCount()];
            Kinematics kin = new Kinematics(m);
            for (int trial = 0; trial < 10; trial++) {
                double[] pose = TestSupport.randomPose(m, rng, 0.02);
                sim.reset(pose, trial);
                sim.readJoints(q, qd);
                assertArrayEquals(pose, q, 1e-9);
                Frame[] frames = kin.forward(pose);
                for (int b = 0; b < m.bodyCount(); b++) {
                    assertEquals(0, sim.bodyFrame(b).origin().distance(frames[b].origin()), 1e-9);
                }
            }
        }
    }

    @Test
    void anArmSpinningFarFasterThanAnyCatchIsReportedAsDiverged() {
        // 2,000 N m on the wrist (its torque limit is about 10 N m) spins the 0.25 kg palm past 2,000 rad/s
        // within its free range; in seeded catch loops the palm turns at most about 150 rad/s, limp about 1,300
        try (OdeSimulator sim = new OdeSimulator(m, config)) {
            sim.reset(m.poseVector("neutral"), 1);
            double[] tau = new double[m.dofCount()];
            tau[m.dof("wrist_flexion").index()] = 2000;
            sim.setJointTorques(tau);
            SimulationDiverged e = assertThrows(SimulationDiverged.class, () -> {
                for (int k = 0; k < steps(config, 0.01); k++) {
                    sim.step();
                }
            });
            assertTrue(e.getMessage().contains("body palm spins at") && e.getMessage().contains("rad/s"), e.getMessage());
        }
    }

    @Test
    void pdHoldsTheNeutralPoseAgainstGravity() {
        try (OdeSimulator sim = new OdeSimulator(m, config)) {
            double[] neutral = m.poseVector("neutral");
            sim.reset(neutral, 1);
            ServoLoop loop = new ServoLoop(sim, TestSupport.pd(m));
            System.arraycopy(neutral, 0, loop.targets(), 0, neutral.length);
            loop.step(steps(config, 2.0));
            double[] q = new double[m.dofCount()], qd = new double[m.dofCount()];
            sim.readJoints(q, qd);
            for (int i = 0; i < q.length; i++) {
                // static sag = gravity torque / kp of eq. (4): under 0.2 deg for the stiff arm
                // joints (kp > 100 N m/rad), under 3 deg for the soft finger joints (kp 0.1-1)
                double tolDeg = i < 7 ? 0.2 : 3.0;
                assertEquals(neutral[i], q[i], Math.toRadians(tolDeg), m.dofs().get(i).name());
                assertEquals(0, qd[i], 0.05, m.dofs().get(i).name() + " should be at rest");
            }
        }
    }

    @Test
    void jointStopsHoldAtTheModelLimitsInBothDirections() {
        String[] dofs = {"elbow_flexion", "wrist_flexion", "wrist_deviation", "index_mcp_flexion", "index_mcp_abduction",
            "index_pip_flexion", "thumb_cmc_abduction", "shoulder_rotation"};
        for (boolean upper : new boolean[] {true, false}) {
            try (OdeSimulator sim = new OdeSimulator(m, config)) {
                double[] neutral = m.poseVector("neutral");
                sim.reset(neutral, 2);
                ServoLoop loop = new ServoLoop(sim, TestSupport.pd(m));
                System.arraycopy(neutral, 0, loop.targets(), 0, neutral.length);
                for (String name : dofs) {
                    var d = m.dof(name);
                    // drive 0.3 rad past the limit: the PD pushes, only the stop can hold it
                    loop.targets()[d.index()] = upper ? d.upper() + 0.3 : d.lower() - 0.3;
                }
                loop.step(steps(config, 1.5));
                double[] q = new double[m.dofCount()], qd = new double[m.dofCount()];
                sim.readJoints(q, qd);
                for (String name : dofs) {
                    var d = m.dof(name);
                    double limit = upper ? d.upper() : d.lower();
                    // a stop holds its joint within ~1 deg of the limit (soft stop, ERP 0.2)
                    assertEquals(limit, q[d.index()], Math.toRadians(1.5), name + (upper ? " upper" : " lower"));
                }
            }
        }
    }

    @Test
    void ballThrownIntoTheCuppedHandIsHeldForThreeSecondsByContactsAlone() {
        ObjectSpec ball = TestSupport.object("sphere");
        try (OdeSimulator sim = new OdeSimulator(m, config)) {
            HeldBallScenario scenario = new HeldBallScenario(new ServoLoop(sim, TestSupport.pd(m)), ball, 0.2, 3);
            Site palm = m.site("palm_center");
            int n = steps(config, HeldBallScenario.FLIGHT_TIME + 0.5 + 3.0);
            double maxDepth = 0;
            for (int i = 0; i < n; i++) {
                scenario.step();
                maxDepth = Math.max(maxDepth, sim.handContacts().maxDepth());
            }
            assertTrue(scenario.contactTime() < HeldBallScenario.FLIGHT_TIME + 0.05, "the ball reaches the palm");
            Frame palmFrame = sim.bodyFrame(palm.body()).compose(new Frame(palm.position(), palm.orientation()));
            RigidState s = sim.objectState();
            Vec3 inPalm = palmFrame.pointFromWorld(s.position());
            // resting in the cup: about one radius above the palm centre (the palm frame's y axis
            // points out of the back of the hand; the cup's rims lift it by up to 1 cm) and within
            // the cup's half-width (2.5 cm) of its centre
            assertEquals(-ball.halfThickness(), inPalm.y(), 0.01);
            assertTrue(Math.hypot(inPalm.x(), inPalm.z()) < 0.025, "ball near the palm centre: " + inPalm);
            assertTrue(s.velocity().norm() < 0.01, "ball at rest in the hand: " + s.velocity());
            assertTrue(sim.handContacts().bodyCount() >= 3, "held by palm and fingers");
            // compliant contacts: penetration stays small (kp = 5e4 N/m)
            assertTrue(maxDepth < 0.003, "max penetration " + maxDepth);
        }
    }

    @Test
    void restingContactHasTheStiffnessOfSection41AndNoBounce() {
        ObjectSpec ball = TestSupport.object("sphere");
        double r = ball.halfThickness(), mass = ball.mass().mass();
        try (OdeSimulator sim = new OdeSimulator(m, config)) {
            sim.reset(m.poseVector("neutral"), 4);
            Vec3 boxCentre = new Vec3(0.6, 0.3, 0.6);
            sim.addStaticBox(boxCentre, new Vec3(0.2, 0.2, 0.2));
            double top = boxCentre.y() + 0.1;
            sim.spawnObject(ball, RigidState.at(new Vec3(0.6, top + r + 0.005, 0.6), Vec3.ZERO));
            double maxAfterContact = Double.NEGATIVE_INFINITY;
            boolean touched = false;
            for (int i = 0; i < steps(config, 1.0); i++) {
                sim.step();
                touched |= sim.objectTouchesBox();
                if (touched) {
                    maxAfterContact = Math.max(maxAfterContact, sim.objectState().position().y());
                }
            }
            // equilibrium of the spring kp: penetration = m g / kp (about 20 micrometres)
            double expected = mass * 9.81 / config.contactStiffness();
            double penetration = top + r - sim.objectState().position().y();
            assertEquals(expected, penetration, 0.1 * expected);
            // critical damping: after touching, the ball never rises back above the surface
            assertTrue(maxAfterContact < top + r, "the ball bounced to " + (maxAfterContact - top - r) + " m");
        }
    }

    @Test
    void sameSeedGivesABitIdenticalWorldAfterOneSecond() {
        double[][] a = runHeldBall(5);
        double[][] b = runHeldBall(5);
        assertArrayEquals(a[0], b[0], 0.0);
        assertArrayEquals(a[1], b[1], 0.0);
    }

    /**
     * A planner tries throws in a twin world restored from the real one's state, so the twin must
     * step on exactly as the real world: the can tumbling into the closing hand, captured 0.1 s
     * after it touched, then 0.4 s more of contact in both worlds. Bit for bit (tolerance 0), as
     * two runs of one seed are (sameSeedGivesABitIdenticalWorldAfterOneSecond).
     */
    @Test
    void aTwinWorldRestoredFromACapturedStateStepsOnBitForBit() {
        ObjectSpec can = TestSupport.object("can");
        try (OdeSimulator real = new OdeSimulator(m, config); Simulator twin = IsolatedEngine.simulator(m, config)) {
            HeldBallScenario scenario = new HeldBallScenario(new ServoLoop(real, TestSupport.pd(m)), can, 0.1, 7);
            for (int i = 0; i < steps(config, HeldBallScenario.FLIGHT_TIME + 0.1); i++) {
                scenario.step();
            }
            assertTrue(real.handContacts().bodyCount() > 0, "the can is in the hand when the state is captured");
            WorldState captured = real.captureState();
            twin.spawnObject(TestSupport.object("sphere"), RigidState.at(new Vec3(0, 2, 0), Vec3.ZERO)); // replaced by the restore
            twin.restoreState(captured);
            assertEquals(captured.time(), twin.time(), 0.0);
            ServoLoop realLoop = new ServoLoop(real, TestSupport.pd(m));
            ServoLoop twinLoop = new ServoLoop(twin, TestSupport.pd(m));
            double[] neutral = m.poseVector("neutral");
            System.arraycopy(neutral, 0, realLoop.targets(), 0, neutral.length);
            System.arraycopy(neutral, 0, twinLoop.targets(), 0, neutral.length);
            for (int i = 0; i < steps(config, 0.4); i++) {
                realLoop.step();
                twinLoop.step();
            }
            assertTrue(real.handContacts().bodyCount() > 0, "still touching: the contacts were part of the comparison");
            assertArrayEquals(real.captureState().bodies(), twin.captureState().bodies(), 0.0);
            assertEquals(real.objectState(), twin.objectState());
            assertEquals(real.stepCount(), twin.stepCount());
        }
    }

    @Test
    void aStateOfAnotherModelIsRefusedWithBothSizes() {
        try (OdeSimulator sim = new OdeSimulator(m, config)) {
            WorldState state = sim.captureState();
            WorldState wrong = new WorldState(0, 0, new double[WorldState.PER_BODY * 2], new double[3],
                    java.util.Optional.empty(), java.util.Optional.empty(), java.util.List.of(), 1);
            var e = assertThrows(IllegalArgumentException.class, () -> sim.restoreState(wrong));
            assertTrue(e.getMessage().contains("2 bodies and 3 DOFs"), e.getMessage());
            sim.restoreState(state); // its own state is fine
        }
    }

    private double[][] runHeldBall(long seed) {
        try (OdeSimulator sim = new OdeSimulator(m, config)) {
            HeldBallScenario s = new HeldBallScenario(new ServoLoop(sim, TestSupport.pd(m)), TestSupport.object("sphere"), 0.2, seed);
            for (int i = 0; i < steps(config, 1.0); i++) {
                s.step();
            }
            double[] q = new double[m.dofCount()], qd = new double[m.dofCount()];
            sim.readJoints(q, qd);
            RigidState o = sim.objectState();
            return new double[][] {q, {o.position().x(), o.position().y(), o.position().z(), o.velocity().x(),
                o.velocity().y(), o.velocity().z()}};
        }
    }
}
