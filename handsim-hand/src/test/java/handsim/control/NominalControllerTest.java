package handsim.control;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.Home;
import handsim.kin.Frame;
import handsim.kin.Kinematics;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.sim.RigidState;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The FSM of the nominal controller without any physics: the joints follow the targets exactly
 * (perfect tracking), the object flies ballistically, and contact is whatever the test says.
 */
@Tag("fast")
class NominalControllerTest {

    static final Vec3 GRAVITY = new Vec3(0, -9.81, 0);
    private final HandModel model = TestSupport.model();
    private final ControllerConfig config = ControllerConfig.load(Home.resolve("configs/controller.json"));
    private final double tick = config.periodSteps() * TestSupport.simConfig().timeStep();
    private final Kinematics kin = new Kinematics(model);
    private final NominalController controller = new NominalController(model, config, TestSupport.object("sphere"), GRAVITY);
    /** Every throw of these tests: the nominal one for a 1.2 m apex, caught as the config says. */
    private final ThrowDecision nominal = ThrowDecision.of(config.nominalThrows().forHeight(1.2));
    private final RigidState launch = RigidState.at(new Vec3(0.05, 1.2, 1.2), new Vec3(0, 1.0, -1.3));

    @Test
    void statesFollowEachOtherOnTheirConfiguredDurations() {
        ControllerState s = controller.start(observe(0, model.poseVector("neutral"), false));
        double catchDuration = s.plan().duration();
        Map<Phase, Double> began = new EnumMap<>(Phase.class);
        List<Phase> order = new ArrayList<>(List.of(Phase.CATCH));
        began.put(Phase.CATCH, 0.0);
        Phase last = Phase.CATCH;
        for (double t = tick; order.size() < 5; t += tick) {
            advance(controller, observe(t, s.targets().clone(), false), s, nominal);
            if (s.phase() != last) {
                order.add(s.phase());
                began.putIfAbsent(s.phase(), t);
                last = s.phase();
            }
        }
        assertEquals(List.of(Phase.CATCH, Phase.MIDDLE, Phase.THROW, Phase.GOBACK, Phase.CATCH), order);
        // a state ends at the first tick at or after its duration: at most one tick late
        assertNear(catchDuration, began.get(Phase.MIDDLE), "CATCH lasts until the planned interception");
        assertNear(config.middleDuration(), began.get(Phase.THROW) - began.get(Phase.MIDDLE), "MIDDLE duration");
        assertNear(config.throwDuration(), began.get(Phase.GOBACK) - began.get(Phase.THROW), "THROW duration");
    }

    @Test
    void handOpensInCatchAndClosesOnTheFirstContact() {
        ControllerState s = controller.start(observe(0, model.poseVector("neutral"), false));
        assertEquals(HandPose.OPEN, s.handPose(), "CATCH opens the hand");
        double t = tick;
        for (int i = 0; i < 20; i++, t += tick) {
            advance(controller, observe(t, s.targets().clone(), false), s, nominal);
        }
        assertEquals(Phase.CATCH, s.phase());
        assertEquals(HandPose.OPEN, s.handPose(), "no contact: the hand stays open");
        advance(controller, observe(t, s.targets().clone(), true), s, nominal);
        assertEquals(HandPose.CLOSED, s.handPose(), "first contact closes the hand (sec. 3.1)");
        assertTrue(s.closedOnContact());
        // the finger targets move from open toward closed over closeTime
        double[] w = s.poseWeights(t + config.closeTime());
        assertEquals(1.0, w[HandPose.CLOSED.ordinal()], 1e-12, "fully closed after closeTime");
    }

    @Test
    void contactOutsideCatchingDoesNotCloseTheHand() {
        ControllerState s = controller.start(observe(0, model.poseVector("neutral"), false));
        double t = tick;
        while (s.phase() != Phase.GOBACK) {
            advance(controller, observe(t, s.targets().clone(), false), s, nominal);
            t += tick;
        }
        advance(controller, observe(t, s.targets().clone(), true), s, nominal);
        assertFalse(s.closedOnContact(), "a touch while going back is not a catch");
        assertEquals(HandPose.NEUTRAL, s.handPose());
    }

    private void assertNear(double expected, double actual, String what) {
        assertTrue(actual >= expected - 1e-9 && actual <= expected + tick + 1e-9,
                what + ": expected " + expected + " (+ one tick " + tick + "), got " + actual);
    }

    /** Perfect tracking: joint angles are the last targets; the object on its ballistic arc from the launch. */
    @Test
    void aClosedLoopReleaseEndsThrowOnTheObjectsPredictedTurnOrRunsItOn() {
        // the release of ClosedLoopRelease: THROW ends once the can would turn 270 deg in flight
        // (not before 0.05 s), and runs up to 0.04 s past its duration while it would turn less
        ClosedLoopRelease release = new ClosedLoopRelease(Math.toRadians(270), 0.05, 0.04);
        NominalController withRelease = new NominalController(model, config.withRelease(release), TestSupport.object("can"), GRAVITY);
        // rising at 3 m/s from 1.0 m, the can comes down through the 0.72 m interception plane
        // after 0.69 s: turning end over end at 20 rad/s it would turn some 800 deg, at rest not at all
        RigidState spinning = new RigidState(new Vec3(0.05, 1.0, 0.5), Quat.IDENTITY, new Vec3(0, 3, 0), new Vec3(20, 0, 0));
        RigidState still = new RigidState(new Vec3(0.05, 1.0, 0.5), Quat.IDENTITY, new Vec3(0, 3, 0), Vec3.ZERO);
        assertEquals(0.05, throwLength(withRelease, spinning), tick + 1e-9, "ends at the earliest tick it may");
        assertEquals(config.throwDuration() + 0.04, throwLength(withRelease, still), tick + 1e-9, "runs on by the extension");
        assertEquals(config.throwDuration(), throwLength(controller, spinning), tick + 1e-9, "without a release: on time");
    }

    @Test
    void theCatchAfterAThrowMeetsTheObjectAsTheTaskOrTheDecisionSays() {
        NominalController taskCatch = new NominalController(model, config.withCatchAfterThrow(new CatchStyle(0.1, 0.45)),
                TestSupport.object("sphere"), GRAVITY);
        CatchPlanner.Plan throwIn = taskCatch.start(observe(0, model.poseVector("neutral"), false)).plan();
        assertEquals(config.catchVelocityFraction(), throwIn.palmVelocity().y() / throwIn.objectVelocity().y(), 1e-9,
                "the throw-in is caught as the controller's own (sec. 3.6: 70 %)");
        CatchPlanner.Plan styledThrowIn = taskCatch.start(observe(0, model.poseVector("neutral"), false), new CatchStyle(-0.05, 0.4))
                .plan();
        assertEquals(config.interceptionHeight() - 0.05, styledThrowIn.objectPosition().y(), 1e-9, "a throw-in style of its own");
        assertEquals(0.4, styledThrowIn.palmVelocity().y() / styledThrowIn.objectVelocity().y(), 1e-9);
        CatchPlanner.Plan afterThrow = catchAfterThrow(taskCatch, nominal);
        assertEquals(config.interceptionHeight() + 0.1, afterThrow.objectPosition().y(), 1e-9, "met on the raised plane");
        assertEquals(0.45, afterThrow.palmVelocity().y() / afterThrow.objectVelocity().y(), 1e-9);

        ThrowDecision choosing = new ThrowDecision(config.nominalThrows().forHeight(1.2), new CatchStyle(-0.05, 0.3));
        CatchPlanner.Plan chosen = catchAfterThrow(taskCatch, choosing);
        assertEquals(config.interceptionHeight() - 0.05, chosen.objectPosition().y(), 1e-9, "the decision's choice wins");
        assertEquals(0.3, chosen.palmVelocity().y() / chosen.objectVelocity().y(), 1e-9);
    }

    @Test
    void theObjectsTurnIsSummedFromItsLastTouchOfTheHand() {
        // a can whose long axis (body y) turns 0.02 rad a tick about world z (horizontal: end over
        // end): the controller sums the ticks' turns (EndOverEnd.step) from the last tick the hand
        // touched it (the flip criterion's FlightTracker from the tick after); none is known before
        // the first touch
        NominalController canController = new NominalController(model, config, TestSupport.object("can"), GRAVITY);
        ControllerState s = canController.start(observe(0, model.poseVector("neutral"), false));
        assertEquals(null, s.turnSinceTouch, "not touched yet: no turn known");
        for (int k = 1; k <= 12; k++) {
            canController.update(turnedCan(k, k <= 2), s);
        }
        // touched at ticks 1 and 2, free for ticks 3..12: ten turns of 0.02 rad about +z, from tick 2's axis
        assertEquals(0, s.turnSinceTouch.distance(new Vec3(0, 0, 0.2)), 1e-12, "ten free ticks summed");
        canController.update(turnedCan(13, true), s);
        assertEquals(Vec3.ZERO, s.turnSinceTouch, "a touch starts the count again");
    }

    /** Tick {@code k} of the can turned 0.02 k rad about world z, touching the hand or not. */
    private Observation turnedCan(int k, boolean touched) {
        Observation o = observe(k * tick, model.poseVector("neutral"), touched);
        RigidState can = new RigidState(o.object().position(), Quat.fromAxisAngle(Vec3.Z, 0.02 * k), o.object().velocity(),
                new Vec3(0, 0, 0.02 / tick));
        return new Observation(o.time(), o.q(), o.qd(), o.palm(), o.palmVelocity(), can, o.touchedBodies());
    }

    /** One tick of the controller: at a throw's decision the throw {@code thrown} begins. */
    private static void advance(NominalController c, Observation o, ControllerState s, ThrowDecision thrown) {
        if (c.throwDue(o, s)) {
            c.beginThrow(o, s, thrown);
        } else {
            c.update(o, s);
        }
    }

    /**
     * The plan of the CATCH that follows the first THROW: the launched sphere flies as {@link
     * #observe} has it until the first catch ends, then rises at 3 m/s from 1 m (as if thrown).
     */
    private CatchPlanner.Plan catchAfterThrow(NominalController c, ThrowDecision decision) {
        RigidState rising = RigidState.at(new Vec3(0.05, 1.0, 0.5), new Vec3(0, 3, 0));
        ControllerState s = c.start(observe(0, model.poseVector("neutral"), false));
        double t = tick;
        boolean caught = false;
        boolean thrown = false;
        while (!(thrown && s.phase() == Phase.CATCH)) {
            Observation o = observe(t, s.targets().clone(), false);
            advance(c, caught ? new Observation(o.time(), o.q(), o.qd(), o.palm(), o.palmVelocity(), rising, 0) : o, s, decision);
            caught |= s.phase() != Phase.CATCH;
            thrown |= s.phase() == Phase.THROW;
            t += tick;
        }
        return s.plan();
    }

    /** How long THROW lasts when the object is in state {@code object} throughout it (s). */
    private double throwLength(NominalController c, RigidState object) {
        ControllerState s = c.start(observe(0, model.poseVector("neutral"), false));
        double t = tick;
        while (s.phase() != Phase.THROW) {
            advance(c, observe(t, s.targets().clone(), false), s, nominal);
            t += tick;
        }
        double began = t - tick;
        while (s.phase() == Phase.THROW) {
            Observation o = observe(t, s.targets().clone(), false);
            advance(c, new Observation(o.time(), o.q(), o.qd(), o.palm(), o.palmVelocity(), object, 0), s, nominal);
            t += tick;
        }
        return t - tick - began;
    }

    private Observation observe(double t, double[] q, boolean touched) {
        Frame palm = kin.siteFrame(model.site("palm_center"), q);
        Vec3 p = launch.position().plus(launch.velocity().times(t)).plus(GRAVITY.times(0.5 * t * t));
        Vec3 v = launch.velocity().plus(GRAVITY.times(t));
        long palmBody = 1L << model.body("palm").index();
        return new Observation(t, q, new double[q.length], palm, Vec3.ZERO, RigidState.at(p, v), touched ? palmBody : 0);
    }
}
