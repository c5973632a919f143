package handsim.control;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.sim.ObjectSpec;
import handsim.sim.RigidState;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** Catch planning (sec. 3.6) against launches whose interception is known by construction. */
@Tag("fast")
class CatchPlannerTest {

    static final Vec3 GRAVITY = new Vec3(0, -9.81, 0);
    static final double PLANE = 0.72;
    /** Closed-form ballistics: only rounding separates planner and construction. */
    static final double TOLERANCE = 1e-9;

    private final CatchPlanner planner = new CatchPlanner(new Ballistics(GRAVITY), PLANE, 0.7, 0.12,
            new CatchPlanner.HeadingSearch(Math.toRadians(15), Math.toRadians(90), 0.005, Math.toRadians(2)), 0);
    /** An arm that reaches everywhere: the planner keeps its preferred heading. */
    private static final CatchPlanner.Reach ANYWHERE = palm -> new DlsIk.Residual(0, 0);
    private final Quat ready = Quat.fromAxisAngle(Vec3.X, -Math.PI / 2);
    private final Grasp centred = new Grasp("open", "closed", Vec3.ZERO);

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

            CatchPlanner.Plan plan = planner.plan(RigidState.at(p0, v0), sphere, centred, ready, ANYWHERE);

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
    void canLongAxisLiesAlongTheHandsZAxisAndThePalmTiltsTowardItAsFarAsItsArrivalAllows() {
        // sec. 3.6: for a can the hand's z axis is aligned with the can's long axis (as far as it
        // is square to the back of the hand); the back of the hand faces the incoming velocity,
        // turned toward the velocity's part across the axis by at most the tilt limit (shipped
        // fallingTiltDeg 0: 90 deg times the arrival's horizontal part)
        ObjectSpec can = TestSupport.object("can");
        Vec3 p0 = new Vec3(0.05, 1.1, 1.2);
        Vec3 v0 = new Vec3(0, 1.0, -1.5);
        Quat tilt = Quat.fromAxisAngle(Vec3.Z, Math.toRadians(70)); // long axis (object y) tipped toward -x
        CatchPlanner.Plan plan = planner.plan(new RigidState(p0, tilt, v0, Vec3.ZERO), can, centred, ready, ANYWHERE);
        Vec3 axis = tilt.rotate(can.longAxis().orElseThrow());
        Quat r = plan.palmTarget().rotation();
        Vec3 v = plan.objectVelocity().normalized();
        Vec3 across = v.minus(axis.times(v.dot(axis))).normalized();
        double horizontal = Math.hypot(v.x(), v.z());
        double expectedTilt = Math.min(Math.acos(v.dot(across)), Math.PI / 2 * horizontal);
        Vec3 back = r.yAxis();
        assertEquals(expectedTilt, Math.acos(Math.min(1, back.dot(v))), 1e-9, "tilt of the back away from the velocity");
        assertEquals(0, back.dot(v.cross(across)), 1e-9, "tilted toward the part across the axis");
        Vec3 axisOffBack = axis.minus(back.times(axis.dot(back))).normalized();
        assertEquals(1.0, Math.abs(r.zAxis().dot(axisOffBack)), 1e-9, "hand z along the long axis");
    }

    @Test
    void aTiltedCanFallingStraightDownIsMetWithALevelPalm() {
        // falling vertically, the can comes down onto a level palm (shipped fallingTiltDeg 0),
        // with the hand's z axis along the long axis's horizontal part
        ObjectSpec can = TestSupport.object("can");
        Quat tilt = Quat.fromAxisAngle(Vec3.Z, Math.toRadians(40));
        RigidState falling = new RigidState(new Vec3(0.05, 1.3, 0.35), tilt, new Vec3(0, -1, 0), Vec3.ZERO);
        Quat r = planner.plan(falling, can, centred, ready, ANYWHERE).palmTarget().rotation();
        assertVec(new Vec3(0, -1, 0), r.yAxis(), "back of the hand down: the palm level");
        Vec3 axis = tilt.rotate(can.longAxis().orElseThrow());
        Vec3 level = new Vec3(axis.x(), 0, axis.z()).normalized();
        assertEquals(1.0, Math.abs(r.zAxis().dot(level)), 1e-9, "hand z along the axis's horizontal part");
    }

    @Test
    void aClubRollingAboutItsAxisIsMetWhereItsAxisPrecessesTo() {
        // a club rolls about its long axis as it tumbles; torque-free, the axis turns about the
        // constant angular momentum at |L| / I_transverse (closed form for a symmetric top), so the
        // hand's z axis must lie along that axis's horizontal part at the interception (cosine to
        // 1e-4: FreeRotation's integration); turning the axis by the whole angular velocity misses
        ObjectSpec club = TestSupport.object("club");
        var inertia = club.mass().inertia();
        assertEquals(inertia.xx(), inertia.zz(), 1e-12, "the club is a symmetric top about its y axis");
        Quat q0 = Quat.fromAxisAngle(Vec3.Y, 0.4).mul(Quat.fromAxisAngle(Vec3.Z, Math.PI / 2)); // axis level
        Vec3 axis0 = q0.rotate(Vec3.Y);
        Vec3 across = Vec3.Y.cross(axis0).normalized(); // horizontal, square to the axis: end over end
        Vec3 w0 = axis0.times(-25).plus(across.times(10));
        RigidState falling = new RigidState(new Vec3(0.05, 1.6, 0.35), q0, new Vec3(0, -0.5, 0), w0);

        CatchPlanner.Plan plan = planner.plan(falling, club, centred, ready, ANYWHERE);

        Vec3 l = axis0.times(inertia.yy() * -25).plus(across.times(inertia.xx() * 10));
        Vec3 axis = Quat.fromAxisAngle(l.normalized(), l.norm() / inertia.xx() * plan.duration()).rotate(axis0);
        Vec3 level = new Vec3(axis.x(), 0, axis.z()).normalized();
        assertVec(new Vec3(0, -1, 0), plan.palmTarget().rotation().yAxis(), "back of the hand down: the palm level");
        assertEquals(1.0, Math.abs(plan.palmTarget().rotation().zAxis().dot(level)), 1e-4, "hand z along the axis's horizontal part");
        Vec3 naive = Quat.fromRotationVector(w0.times(plan.duration())).rotate(axis0);
        Vec3 naiveLevel = new Vec3(naive.x(), 0, naive.z()).normalized();
        assertTrue(Math.abs(naiveLevel.dot(level)) < 0.99, "the constant-w axis would be another heading");
    }

    /**
     * A can dropped from rest at 1.1 m tumbling end over end at 15 rad/s about a principal axis
     * (a steady turn: the long axis turns at 15 rad/s about world z); it crosses the plane 0.72 at
     * T0 = sqrt(2 0.38 / g) with its axis 60 deg from the vertical, 30 deg out of level, and met
     * with a level search {@code below} and {@code above} the plane, in 1 cm steps, 5 deg.
     */
    private CatchPlanner.Plan tumblingCanMet(double below, double above) {
        double t0 = fallTime(PLANE);
        Quat q0 = Quat.fromAxisAngle(Vec3.Z, Math.toRadians(60) - 15 * t0);
        RigidState can = new RigidState(new Vec3(0.05, 1.1, 0.35), q0, Vec3.ZERO, new Vec3(0, 0, 15));
        CatchStyle level = new CatchStyle(0, 0.7, new CatchStyle.Level(below, above, 0.01, Math.toRadians(5)));
        return planner.plan(can, TestSupport.object("can"), centred, ready, ANYWHERE, level);
    }

    /** Time for the can dropped from rest at 1.1 m to fall to height {@code y}. */
    private static double fallTime(double y) {
        return Math.sqrt(2 * (1.1 - y) / 9.81);
    }

    @Test
    void aLevelCatchWaitsForTheNearestLowerPlaneWhereTheTumblingAxisLiesLevel() {
        // by construction the axis is 60 + 15 (t - T0) rad-turned from the vertical: on the plane
        // 0.08 m lower it is still 6.0 deg out of level, on the plane 0.09 m lower 3.1 deg, the
        // first within the 5 deg that count as level; closed-form ballistics give that time
        CatchPlanner.Plan plan = tumblingCanMet(0.15, 0);
        assertEquals(fallTime(PLANE - 0.09), plan.duration(), TOLERANCE, "met 0.09 m below the plane");
        assertEquals(PLANE - 0.09, plan.objectPosition().y(), TOLERANCE, "centre on the lowered plane");
        // the search tries nearest first, either way: with room above as well it still goes down
        assertEquals(fallTime(PLANE - 0.09), tumblingCanMet(0.15, 0.15).duration(), TOLERANCE, "the same with room above");
    }

    @Test
    void aLevelCatchThatCannotReachLevelTakesThePlaneNearestToIt() {
        // within 0.05 m below the axis is never within 5 deg of level; it comes nearest on the
        // lowest plane tried, as it turns toward level all the way down; above the plane it is
        // further from level, so a search only upward stays on the plane
        assertEquals(fallTime(PLANE - 0.05), tumblingCanMet(0.05, 0).duration(), TOLERANCE, "met 0.05 m below the plane");
        assertEquals(fallTime(PLANE), tumblingCanMet(0, 0.15).duration(), TOLERANCE, "met on the plane");
    }

    /**
     * The tumbling can of {@link #tumblingCanMet}, searched 0.15 m down in 1 cm steps for an axis
     * within 5 deg of level that has also turned {@code minTurnDeg} since it left the hand,
     * having turned {@code turnSoFar} (rad, about world z) before now.
     */
    private CatchPlanner.Plan tumblingCanTurned(double minTurnDeg, double turnSoFar) {
        return tumblingCanTurned(minTurnDeg, 5, new Vec3(0, 0, turnSoFar));
    }

    /** The same, a plane met for its turn within {@code turnTiltDeg} of level; {@code turnSoFar} null when not known. */
    private CatchPlanner.Plan tumblingCanTurned(double minTurnDeg, double turnTiltDeg, Vec3 turnSoFar) {
        double t0 = fallTime(PLANE);
        Quat q0 = Quat.fromAxisAngle(Vec3.Z, Math.toRadians(60) - 15 * t0);
        RigidState can = new RigidState(new Vec3(0.05, 1.1, 0.35), q0, Vec3.ZERO, new Vec3(0, 0, 15));
        CatchStyle style = new CatchStyle(0, 0.7,
                new CatchStyle.Level(0.15, 0, 0.01, Math.toRadians(5), Math.toRadians(minTurnDeg), Math.toRadians(turnTiltDeg)));
        return planner.plan(can, TestSupport.object("can"), centred, ready, ANYWHERE, style, turnSoFar);
    }

    @Test
    void aTurnedCatchWaitsUntilTheCanHasAlsoTurnedFarEnough() {
        // the steady tumble turns the axis 15 t rad about z: on the plane 0.09 m lower (3.2 deg out
        // of level, the plain level catch) it has turned 266.0 deg, 0.10 m lower 268.9 deg (0.4
        // deg out of level), 0.11 m lower 271.6 deg (2.4 deg), 0.12 m lower 5.2 deg out of level
        assertEquals(fallTime(PLANE - 0.10), tumblingCanTurned(267, 0).duration(), TOLERANCE, "0.10 m lower: turned 268.9 deg");
        assertEquals(fallTime(PLANE - 0.09), tumblingCanTurned(260, 0).duration(), TOLERANCE, "turned enough on the level plane");
        // the turn before now adds: 5.7 deg more makes 0.09 m lower 271.7 deg, short of 272, 0.10 m 274.6
        assertEquals(fallTime(PLANE - 0.10), tumblingCanTurned(272, 0.1).duration(), TOLERANCE, "the turn so far counts");
        // turned 272 deg nowhere within 5 deg of level: the most turned plane within it, 0.11 m lower
        assertEquals(fallTime(PLANE - 0.11), tumblingCanTurned(272, 0).duration(), TOLERANCE, "the most turned plane");
        // with planes met for their turn up to 10 deg out of level: 0.13 m lower (7.9 deg, 277.1
        // deg) is the nearest turned 275 deg; the level ones (0.09-0.11 m) are not
        assertEquals(fallTime(PLANE - 0.13), tumblingCanTurned(275, 10, Vec3.ZERO).duration(), TOLERANCE,
                "the nearest turned plane within the turn tilt");
        // no turn asked, or none known: the plain level catch, 0.09 m lower
        assertEquals(fallTime(PLANE - 0.09), tumblingCanTurned(0, 10, Vec3.ZERO).duration(), TOLERANCE, "no turn asked");
        assertEquals(fallTime(PLANE - 0.09), tumblingCanTurned(275, 10, null).duration(), TOLERANCE, "turn so far unknown");
    }

    @Test
    void thePredictedTurnSumsTheAxissTurnsAlongTheFreeFlight() {
        ObjectSpec can = TestSupport.object("can");
        // the axis (body y) upright, end over end about world z, a principal axis: 15 rad/s for
        // 0.3 s, plus 0.5 rad before; steady, so the sum is exact to rounding
        RigidState tumbling = new RigidState(new Vec3(0, 1, 0), Quat.IDENTITY, Vec3.ZERO, new Vec3(0, 0, 15));
        assertEquals(0.5 + 4.5, planner.predictedTurn(tumbling, can, new Vec3(0, 0, 0.5), 0.3), 1e-9, "steady tumble");
        // turning back against the turn so far takes it off
        assertEquals(4.5 - 0.5, planner.predictedTurn(tumbling, can, new Vec3(0, 0, -0.5), 0.3), 1e-9, "turns back cancel");
        // a flat spin: the axis (body y) lying along world x, turning about the vertical, turns
        // about the vertical only: no end-over-end turn
        RigidState spinning = new RigidState(new Vec3(0, 1, 0), Quat.fromAxisAngle(Vec3.Z, -Math.PI / 2), Vec3.ZERO,
                new Vec3(0, 15, 0));
        assertEquals(0, planner.predictedTurn(spinning, can, Vec3.ZERO, 0.3), 1e-9, "flat spin");
    }

    @Test
    void graspOffsetPlacesTheObjectOnTheHand() {
        // the object's centre arrives at (0, -halfThickness, 0) + offset in the palm frame
        ObjectSpec can = TestSupport.object("can");
        Grasp distal = new Grasp("open", "closed", new Vec3(0.03, -0.01, 0.005));
        RigidState launch = new RigidState(new Vec3(0.05, 1.1, 1.2), Quat.fromAxisAngle(Vec3.Z, 1.2), new Vec3(0, 1.0, -1.5),
                Vec3.ZERO);
        CatchPlanner.Plan plan = planner.plan(launch, can, distal, ready, ANYWHERE);
        Vec3 inPalm = plan.palmTarget().rotation().inverseRotate(plan.objectPosition().minus(plan.palmTarget().origin()));
        assertVec(new Vec3(0.03, -can.halfThickness() - 0.01, 0.005), inPalm, "object centre in the palm frame");
    }

    @Test
    void aStyleOffsetMovesWhereTheObjectIsMetOnTheHand() {
        // the style's offset adds to the grasp's, in the palm frame; the interception itself (time,
        // point, palm rotation) is the grasp's own, so only the palm's position moves
        ObjectSpec can = TestSupport.object("can");
        Grasp distal = new Grasp("open", "closed", new Vec3(0.045, 0, 0));
        RigidState launch = new RigidState(new Vec3(0.05, 1.1, 1.2), Quat.fromAxisAngle(Vec3.Z, 1.2), new Vec3(0, 1.0, -1.5),
                Vec3.ZERO);
        CatchPlanner.Plan plain = planner.plan(launch, can, distal, ready, ANYWHERE, new CatchStyle(0, 0.7));
        CatchPlanner.Plan shifted = planner.plan(launch, can, distal, ready, ANYWHERE,
                new CatchStyle(0, 0.7, null, new Vec3(0, 0, -0.01)));
        Vec3 inPalm = shifted.palmTarget().rotation().inverseRotate(shifted.objectPosition().minus(shifted.palmTarget().origin()));
        assertVec(new Vec3(0.045, -can.halfThickness(), -0.01), inPalm, "object centre 1 cm toward the thumb");
        assertEquals(plain.duration(), shifted.duration(), 0, "met at the same time");
        assertVec(plain.objectPosition(), shifted.objectPosition(), "at the same point");
        assertEquals(0, plain.palmTarget().rotation().angleTo(shifted.palmTarget().rotation()), 1e-12, "with the same palm rotation");
    }

    @Test
    void unreachableHeadingsTurnThePalmToTheNearestReachableOne() {
        // an arm that can only hold the palm with its z axis within 20 deg of a direction 50 deg
        // round the palm normal from the preferred heading: of the tried turns (0, +-15, +-30,
        // +-45, ...) only +45 and +60 are within 20 deg, and the search takes the smaller
        ObjectSpec sphere = TestSupport.object("sphere");
        RigidState launch = RigidState.at(new Vec3(0.05, 1.1, 1.2), new Vec3(0, 1.0, -1.5));
        Quat preferred = planner.plan(launch, sphere, centred, ready, ANYWHERE).palmTarget().rotation();
        Vec3 allowed = preferred.mul(Quat.fromAxisAngle(Vec3.Y, Math.toRadians(50))).zAxis();
        CatchPlanner.Reach narrow = palm -> palm.rotation().zAxis().dot(allowed) > Math.cos(Math.toRadians(20))
                ? new DlsIk.Residual(0, 0) : new DlsIk.Residual(0.1, 0.5);
        Quat turned = planner.plan(launch, sphere, centred, ready, narrow).palmTarget().rotation();
        assertEquals(Math.toRadians(45), preferred.angleTo(turned), 1e-9, "turned by the first reachable step");
        assertVec(preferred.yAxis(), turned.yAxis(), "turned about the palm normal only");
    }

    @Test
    void withNoReachableHeadingThePlannerKeepsTheBestReachedOne() {
        // every frame is out of reach; the miss is smallest 30 deg round from the preferred heading
        ObjectSpec sphere = TestSupport.object("sphere");
        RigidState launch = RigidState.at(new Vec3(0.05, 1.1, 1.2), new Vec3(0, 1.0, -1.5));
        Quat preferred = planner.plan(launch, sphere, centred, ready, ANYWHERE).palmTarget().rotation();
        Vec3 best = preferred.mul(Quat.fromAxisAngle(Vec3.Y, Math.toRadians(-30))).zAxis();
        CatchPlanner.Reach nowhere = palm -> new DlsIk.Residual(0.1 + 0.1 * (1 - palm.rotation().zAxis().dot(best)), 0);
        Quat turned = planner.plan(launch, sphere, centred, ready, nowhere).palmTarget().rotation();
        assertEquals(Math.toRadians(30), preferred.angleTo(turned), 1e-9, "the least-miss heading");
    }

    @Test
    void objectBelowThePlaneIsMetAfterTheMinimumTime() {
        Vec3 p0 = new Vec3(0, 0.5, 0.4);
        CatchPlanner.Plan plan = planner.plan(RigidState.at(p0, new Vec3(0, -1, 0)), TestSupport.object("sphere"), centred, ready, ANYWHERE);
        assertEquals(0.12, plan.duration(), TOLERANCE, "catch.minDuration when the plane was already crossed");
        assertVec(new Vec3(0, 0.5 - 0.12 - 0.5 * 9.81 * 0.12 * 0.12, 0.4), plan.objectPosition(), "ballistic position");
    }

    private static void assertVec(Vec3 expected, Vec3 actual, String what) {
        assertTrue(expected.distance(actual) < 1e-7, what + ": expected " + expected + ", got " + actual);
    }
}
