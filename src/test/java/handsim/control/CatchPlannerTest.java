package handsim.control;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.sim.ObjectSpec;
import handsim.sim.RigidState;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** Catch planning (sec. 3.6) against launches whose interception is known by construction. */
class CatchPlannerTest {

    static final Vec3 GRAVITY = new Vec3(0, -9.81, 0);
    static final double PLANE = 0.72;
    /** Closed-form ballistics: only rounding separates planner and construction. */
    static final double TOLERANCE = 1e-9;

    private final CatchPlanner planner = new CatchPlanner(new Ballistics(GRAVITY), PLANE, 0.7, 0.12);
    private final Quat ready = Quat.fromAxisAngle(Vec3.X, -Math.PI / 2);

    /**
     * Launch a point from p0 so that it is at P (on the plane) after T seconds:
     * v0 = (P - p0 - g T^2 / 2) / T. With p0 above the plane or v0.y large enough, P is reached
     * descending, so the planner must find exactly T, P and v0 + g T.
     */
    @Test
    void interceptionMatchesTheAnalyticBallisticSolution() {
        SplittableRandom rng = new SplittableRandom(3);
        ObjectSpec sphere = TestSupport.object("sphere");
        for (int trial = 0; trial < 50; trial++) {
            Vec3 p = new Vec3(0.1 * rng.nextDouble(), PLANE, 0.3 + 0.2 * rng.nextDouble());
            Vec3 p0 = p.plus(new Vec3(0.4 * rng.nextDouble() - 0.2, 0.2 + 0.4 * rng.nextDouble(), 0.6 + 0.6 * rng.nextDouble()));
            double t = 0.4 + 0.5 * rng.nextDouble();
            Vec3 v0 = p.minus(p0).minus(GRAVITY.times(0.5 * t * t)).times(1 / t);
            Vec3 vArrive = v0.plus(GRAVITY.times(t));
            assertTrue(vArrive.y() < 0, "construction must arrive descending");

            CatchPlanner.Plan plan = planner.plan(RigidState.at(p0, v0), sphere, ready);

            assertEquals(t, plan.duration(), TOLERANCE, "interception time");
            assertVec(p, plan.objectPosition(), "interception point");
            assertVec(vArrive, plan.objectVelocity(), "object velocity at interception");
            // the palm arrives at 70 % of the object's velocity (sec. 3.6)
            assertVec(vArrive.times(0.7), plan.palmVelocity(), "palm velocity");
            // the back of the hand (palm frame +y) faces along the incoming velocity
            Vec3 back = plan.palmTarget().rotation().yAxis();
            assertVec(vArrive.normalized(), back, "back of the hand");
            // the object's centre sits one radius off the palm, on the palm side
            assertVec(p, plan.palmTarget().origin().minus(back.times(sphere.halfThickness())), "palm offset");
        }
    }

    @Test
    void canLongAxisLiesAlongTheHandsZAxis() {
        // sec. 3.6: for a can the hand's z axis is aligned with the can's long axis
        ObjectSpec can = TestSupport.object("can");
        Vec3 p0 = new Vec3(0.05, 1.1, 1.2);
        Vec3 v0 = new Vec3(0, 1.0, -1.5);
        Quat tilt = Quat.fromAxisAngle(Vec3.Z, Math.toRadians(70)); // long axis (object y) tipped toward -x
        CatchPlanner.Plan plan = planner.plan(new RigidState(p0, tilt, v0, Vec3.ZERO), can, ready);
        Vec3 axis = tilt.rotate(can.longAxis().orElseThrow());
        Vec3 back = plan.objectVelocity().normalized();
        Vec3 expected = axis.minus(back.times(axis.dot(back))).normalized();
        Vec3 z = plan.palmTarget().rotation().zAxis();
        assertEquals(1.0, Math.abs(z.dot(expected)), 1e-9, "hand z along the projected long axis");
        assertEquals(0.0, z.dot(plan.palmTarget().rotation().yAxis()), 1e-9, "frame stays orthonormal");
    }

    @Test
    void objectBelowThePlaneIsMetAfterTheMinimumTime() {
        Vec3 p0 = new Vec3(0, 0.5, 0.4);
        CatchPlanner.Plan plan = planner.plan(RigidState.at(p0, new Vec3(0, -1, 0)), TestSupport.object("sphere"), ready);
        assertEquals(0.12, plan.duration(), TOLERANCE, "catch.minDuration when the plane was already crossed");
        assertVec(new Vec3(0, 0.5 - 0.12 - 0.5 * 9.81 * 0.12 * 0.12, 0.4), plan.objectPosition(), "ballistic position");
    }

    private static void assertVec(Vec3 expected, Vec3 actual, String what) {
        assertTrue(expected.distance(actual) < 1e-7, what + ": expected " + expected + ", got " + actual);
    }
}
