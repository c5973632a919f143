package handsim.task;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.TestSupport;
import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.ArmRest;
import handsim.control.CatchStyle;
import handsim.control.ClosedLoopRelease;
import handsim.control.ControllerConfig;
import handsim.control.Phase;
import handsim.math.EndOverEnd;
import handsim.math.Vec3;
import java.nio.file.Files;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Flip detection and eq. (7) on scripted flights: the count comes from the long axis's net
 * end-over-end turn in flight (half turns for a can, whole turns for a club, 45 deg of tolerance
 * in the shipped configs/tasks/flip.json).
 */
@Tag("fast")
class FlipTaskTest {

    private final FlipTask can = (FlipTask) TestSupport.tasks().create("flip", "can");
    private final FlipTask club = (FlipTask) TestSupport.tasks().create("flip", "club");
    private final Vec3 target = TestSupport.neutralPalm().plus(new Vec3(0, 0.12, 0));
    /** The bins of configs/evaluation.json's flipBins: 15 deg, throws 2-5 early, edges 4 and 8 cm. */
    private static final FlipTask.ReportBins BINS = new FlipTask.ReportBins(Math.toRadians(15), 5, new double[] {0.04, 0.08});

    private static LoopRecord flight(double rotationDeg, boolean caught, Vec3 where) {
        return flight(rotationDeg, caught, where, caught ? 10 : Double.NaN);
    }

    private static LoopRecord flight(double rotationDeg, boolean caught, Vec3 where, double catchTiltDeg) {
        return new LoopRecord(1, caught, 1.3, caught ? null : where, Double.NaN, null, false, Double.NaN,
                Math.toRadians(rotationDeg), Double.NaN, Math.toRadians(catchTiltDeg), Double.NaN,
                caught ? where : null, Double.NaN, 0, 0, 0, 1);
    }

    @Test
    void flipsAreCountedInWholeFlipAnglesWithTheTolerance() {
        // can: 180 deg a flip, counted from 135 deg on
        assertEquals(0, can.flips(flight(0, true, target)));
        assertEquals(0, can.flips(flight(130, true, target)), "a near miss: 5 deg short of the tolerance");
        assertEquals(1, can.flips(flight(140, true, target)));
        assertEquals(1, can.flips(flight(180, true, target)));
        assertEquals(2, can.flips(flight(360, true, target)), "two half turns");
        // club: a whole turn brings the handle back
        assertEquals(0, club.flips(flight(180, true, target)));
        assertEquals(1, club.flips(flight(320, true, target)));
        assertEquals(2, club.flips(flight(720, true, target)));
        assertEquals(0, can.flips(new LoopRecord(0, true, Double.NaN, null, Double.NaN, null, false, Double.NaN, Double.NaN,
                Double.NaN, Double.NaN, Double.NaN, null, Double.NaN, 0, 0, 0, 1)), "the throw-in is no flip");
    }

    @Test
    void throwsAreBinnedByFlightRotationInQuarterFlips() {
        // can: quarters of its 180 deg flip, 45 deg wide; the throw-in and a throw with no measured flight are left out
        LoopRecord throwIn = new LoopRecord(0, true, Double.NaN, null, Double.NaN, null, false, Double.NaN, Double.NaN,
                Double.NaN, Double.NaN, Double.NaN, null, Double.NaN, 0, 0, 0, 1);
        var bins = can.byFlightRotation(List.of(throwIn, flight(10, true, target), flight(200, true, target),
                flight(210, true, target), flight(220, false, target), flight(Double.NaN, true, target)));
        assertEquals(5, bins.size(), "0-45 up to 180-225, the empty bins between included");
        assertEquals(Math.toRadians(180), bins.get(4).from(), 1e-12);
        assertEquals(Math.toRadians(225), bins.get(4).to(), 1e-12);
        assertEquals(1, bins.get(0).throwsMade());
        assertEquals(0, bins.get(0).successes(), "10 deg is no flip");
        assertEquals(0, bins.get(2).throwsMade());
        assertEquals(3, bins.get(4).throwsMade());
        assertEquals(2, bins.get(4).successes(), "the dropped one is no success");
        assertTrue(can.byFlightRotation(List.of(throwIn)).isEmpty());
    }

    private static LoopRecord arriving(double arrivalDeg, boolean caught, double catchTiltDeg) {
        return new LoopRecord(1, caught, 1.3, caught ? null : Vec3.ZERO, Double.NaN, null, false, Double.NaN, Math.PI,
                Double.NaN, caught ? Math.toRadians(catchTiltDeg) : Double.NaN, Double.NaN,
                Vec3.ZERO, Math.toRadians(arrivalDeg), 0, 0, 0, 1);
    }

    @Test
    void throwsAreBinnedByHowFarTheAxisStoodOutOfTheHorizontalWhenTheObjectCameBack() {
        // six 15 deg bins from lying (0) to end-first (90), empty ones included; a throw that never came back
        // to the hand (NaN) and the throw-in are left out
        LoopRecord throwIn = new LoopRecord(0, true, Double.NaN, null, Double.NaN, null, false, Double.NaN, Double.NaN,
                Double.NaN, Double.NaN, Double.NaN, null, Math.toRadians(10), 0, 0, 0, 1);
        var bins = can.byArrivalTilt(List.of(throwIn, arriving(5, true, 10), arriving(14, false, 0), arriving(70, true, 80),
                arriving(89, false, 0), arriving(90, true, 85), arriving(Double.NaN, false, 0)), BINS);
        assertEquals(6, bins.size());
        assertEquals(Math.toRadians(75), bins.get(5).from(), 1e-12);
        assertEquals(Math.toRadians(90), bins.get(5).to(), 1e-12);
        assertEquals(new FlipTask.ArrivalBin(0, Math.toRadians(15), 2, 1, 1, 0), bins.get(0), "a flip caught lying, a drop");
        assertEquals(0, bins.get(1).throwsMade());
        assertEquals(1, bins.get(4).standing(), "70 deg: caught standing 80 deg out of the palm");
        assertEquals(2, bins.get(5).throwsMade(), "exactly end-first counts in the last bin");
        assertEquals(1, bins.get(5).drops());
        assertEquals(1, bins.get(5).standing());
    }

    @Test
    void eachFailedThrowFailsForOneReasonTheEndFirstArrivalFirst() {
        // configs/tasks/flip.json: a failed throw that came back with its axis 60 deg or more out of the
        // horizontal arrived end-first, whatever the catch did; otherwise the catch's outcome names it
        assertEquals(java.util.Optional.empty(), can.failure(arriving(10, true, 10)), "flipped (180 deg) and caught lying");
        assertEquals(FlipTask.Failure.ARRIVED_END_FIRST, can.failure(arriving(70, true, 80)).orElseThrow());
        assertEquals(FlipTask.Failure.ARRIVED_END_FIRST, can.failure(arriving(60, false, 0)).orElseThrow(), "60 deg is end-first");
        assertEquals(FlipTask.Failure.DROPPED, can.failure(arriving(59, false, 0)).orElseThrow());
        assertEquals(FlipTask.Failure.DROPPED, can.failure(flight(180, false, target)).orElseThrow(), "never came back (NaN)");
        assertEquals(FlipTask.Failure.CAUGHT_STANDING, can.failure(arriving(40, true, 50)).orElseThrow());
        assertEquals(FlipTask.Failure.NO_FLIP, can.failure(flight(90, true, target, 10)).orElseThrow());
        LoopRecord throwIn = new LoopRecord(0, true, Double.NaN, null, Double.NaN, null, false, Double.NaN, Double.NaN,
                Double.NaN, Double.NaN, Double.NaN, null, Double.NaN, 0, 0, 0, 1);
        FlipTask.ThrowTally t = can.tally(List.of(throwIn, arriving(10, true, 10), arriving(70, true, 80), arriving(59, false, 0),
                flight(90, true, target, 10), arriving(5, true, 20)));
        assertEquals(5, t.throwsMade(), "the throw-in is no throw");
        assertEquals(2, t.successes());
        assertEquals(0.4, t.successRate(), 1e-12);
        assertEquals(java.util.Map.of(FlipTask.Failure.ARRIVED_END_FIRST, 1, FlipTask.Failure.DROPPED, 1,
                FlipTask.Failure.CAUGHT_STANDING, 0, FlipTask.Failure.NO_FLIP, 1), t.failures());
    }

    @Test
    void firstThrowsAreBinnedByTheHeadingTheThrowInRestedAt() {
        // six 15-degree bins from 0 (across the palm) to 90 (along the fingers); 90 itself falls in the last
        List<FlipTask.AngleBin> bins = can.firstThrowsByRestHeading(List.of(
                List.of(restingAt(5), flight(180, true, target)),
                List.of(restingAt(10), flight(90, true, target), flight(180, true, target)),
                List.of(restingAt(50), flight(180, true, target)),
                List.of(restingAt(90), flight(180, false, target)),
                List.of(restingAt(Double.NaN)),
                List.of(restingAt(20))), BINS);
        assertEquals(6, bins.size());
        assertEquals(Math.toRadians(45), bins.get(3).from(), 1e-12);
        assertEquals(Math.toRadians(60), bins.get(3).to(), 1e-12);
        int[] made = bins.stream().mapToInt(FlipTask.AngleBin::throwsMade).toArray();
        int[] succeeded = bins.stream().mapToInt(FlipTask.AngleBin::successes).toArray();
        // only loop 1 counts (episode 2's second throw is left out); a dropped throw-in or one not thrown from is no first throw
        assertArrayEquals(new int[] {2, 0, 0, 1, 0, 1}, made);
        assertArrayEquals(new int[] {1, 0, 0, 1, 0, 0}, succeeded);
    }

    @Test
    void laterThrowsAreCountedByTheRestTheCatchBeforeThemLeft() {
        // flat: under 10 deg out of the palm's plane; askew: 5 deg or more from across the palm
        // (FlipTask.FLAT_REST, ASKEW_REST); throws 2-5 are early, from the 6th later; the first
        // throw (from the throw-in) is not counted, nor a throw after a catch with no tilt measured
        LoopRecord raisedAcross = caughtResting(15, 2), flatAskew = caughtResting(5, 8), flatAcross = caughtResting(9.9, 4.9),
                raisedAskew = caughtResting(10, 5), dropped = flight(180, false, target), failed = flight(90, true, target, 10);
        List<LoopRecord> episode = List.of(restingAt(0), raisedAcross, flatAskew, failed);
        List<LoopRecord> longer = List.of(restingAt(0), flatAskew, raisedAcross, dropped, raisedAskew, flatAcross, flatAskew,
                raisedAcross);
        List<FlipTask.RestCount> counts = can.laterThrowsByRest(List.of(episode, longer), BINS);
        assertEquals(List.of(FlipTask.Rest.values()), counts.stream().map(FlipTask.RestCount::rest).toList(), "all four rests, in order");
        // episode: throw 2 from raised-across succeeds, throw 3 from flat-askew fails (no flip);
        // longer: throw 2 from flat-askew succeeds, 3 from raised-across is dropped, 4 follows the drop
        // (no rest: left out), 5 from raised-askew (10 deg is not flat, 5 deg is askew) succeeds,
        // 6 from flat-across (9.9, 4.9 deg) and 7 from flat-askew succeed as later throws
        assertEquals(List.of(new FlipTask.ThrowsAfter(2, 1, 0, 0), new FlipTask.ThrowsAfter(1, 1, 0, 0), new FlipTask.ThrowsAfter(0, 0, 1, 1),
                new FlipTask.ThrowsAfter(2, 1, 1, 1)), counts.stream().map(FlipTask.RestCount::throwsAfter).toList());
    }

    @Test
    void laterThrowsAreCountedByHowFarFromTheRunsMedianCatchTheCatchBeforeThemWas() {
        // a flip caught at target + (dx, dy, dz); the median of the hand's catches is the target
        // (x offsets 0 0 0 0 0 .01 .10 and z 0 ... .05: medians 0); only the horizontal distance
        // counts (BINS: under 4 cm, 4-8 cm, 8 cm and over); throws 2-5
        // are early, from the 6th later; the throw after a drop (no catch point) is left out
        LoopRecord near = flight(180, true, target), raisedBeside = flight(180, true, target.plus(new Vec3(0.01, 0.3, 0))),
                mid = flight(180, true, target.plus(new Vec3(0, 0, 0.05))), far = flight(180, true, target.plus(new Vec3(0.10, 0, 0))),
                failed = flight(90, true, target), dropped = flight(180, false, target);
        List<LoopRecord> episode = List.of(restingAt(0), near, raisedBeside, mid, far, failed, near, dropped, near);
        FlipTask.CatchDistances d = can.laterThrowsByCatchDistance(List.of(episode), BINS).orElseThrow();
        assertEquals(0, d.medianCatch().minus(target).norm(), 1e-12, "the median of each coordinate");
        assertEquals(List.of(new FlipTask.DistanceCount(0, 0.04, new FlipTask.ThrowsAfter(2, 2, 2, 1)),
                new FlipTask.DistanceCount(0.04, 0.08, new FlipTask.ThrowsAfter(1, 1, 0, 0)),
                new FlipTask.DistanceCount(0.08, Double.POSITIVE_INFINITY, new FlipTask.ThrowsAfter(1, 0, 0, 0))), d.bins());
        assertTrue(can.laterThrowsByCatchDistance(List.of(List.of(restingAt(0)), List.of(restingAt(Double.NaN))), BINS).isEmpty(),
                "no catch of the hand's own: nothing to measure from");
    }

    /** A flip caught and resting {@code tiltDeg} out of the palm's plane, {@code headingDeg} from across it. */
    private LoopRecord caughtResting(double tiltDeg, double headingDeg) {
        return new LoopRecord(1, true, 1.3, null, Double.NaN, null, false, Double.NaN, Math.PI, Double.NaN, Math.toRadians(tiltDeg),
                Math.toRadians(headingDeg), target, Double.NaN, 0, 0, 0, 1);
    }

    /** A caught throw-in resting at {@code headingDeg} in the palm (NaN: dropped). */
    private static LoopRecord restingAt(double headingDeg) {
        return new LoopRecord(0, !Double.isNaN(headingDeg), Double.NaN, null, Double.NaN, null, false, Double.NaN, Double.NaN,
                Double.NaN, 10, Math.toRadians(headingDeg), null, Double.NaN, 0, 0, 0, 1);
    }

    @Test
    void rewardFollowsEquation7() {
        Vec3 off = target.plus(new Vec3(0.05, 0, 0));
        // flipped and caught 5 cm from p_d: exp(-10 * 0.05) + r_flip
        assertEquals(Math.exp(-0.5) + 1, can.reward(flight(180, true, off)), 1e-12);
        assertTrue(can.success(flight(180, true, off)));
        // caught without a flip: the miss term, -0.1 |p_p - p_d|
        assertEquals(-0.1 * 0.05, can.reward(flight(20, true, off)), 1e-12);
        assertFalse(can.success(flight(20, true, off)));
        // flipped but dropped 1 m away
        Vec3 ground = target.plus(new Vec3(0, 0, 1));
        assertEquals(-0.1 * 1, can.reward(flight(200, false, ground)), 1e-12);
    }

    @Test
    void aFlipCountsOnlyWhenTheObjectIsCaughtLyingInTheHand() {
        // configs/tasks/flip.json: the long axis at most 45 deg out of the palm's plane (a flip is caught "aligned with the palm")
        assertTrue(can.success(flight(180, true, target, 0)), "lying flat in the palm");
        assertTrue(can.success(flight(180, true, target, 44)), "1 deg inside the tilt allowed");
        assertFalse(can.success(flight(180, true, target, 46)), "1 deg past it: leaning on the fingers");
        assertFalse(can.success(flight(180, true, target, 85)), "standing on end in the palm");
        assertTrue(can.properCatch(flight(20, true, target, 30)), "a catch without a flip can still be proper");
        assertFalse(can.properCatch(flight(180, false, target)), "a drop is no catch");
        // eq. (7): a flip caught standing scores as a miss, -0.1 |p_p - p_d|
        Vec3 off = target.plus(new Vec3(0.05, 0, 0));
        assertEquals(-0.1 * 0.05, can.reward(flight(180, true, off, 80)), 1e-12);
    }

    @Test
    void anObjectTheConfigDoesNotListIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> TestSupport.tasks().create("flip", "sphere"));
        assertTrue(e.getMessage().contains("sphere") && e.getMessage().contains("can"), e.getMessage());
    }

    @Test
    void onlyEndOverEndTurningCounts() {
        Vec3 up = Vec3.Y;
        double step = Math.toRadians(10);
        // a can lying along x tipped up about the horizontal z axis by 10 deg: all of it counts
        Vec3 tipped = new Vec3(Math.cos(step), Math.sin(step), 0);
        assertEquals(step, EndOverEnd.net(EndOverEnd.step(Vec3.X, tipped), up), 1e-12);
        // the same turn flat, about the vertical (a propeller spin): nothing counts
        Vec3 spun = new Vec3(Math.cos(step), 0, Math.sin(step));
        assertEquals(0, EndOverEnd.net(EndOverEnd.step(Vec3.X, spun), up), 1e-12);
        // about an axis 60 deg from the vertical: the turn times sin 60 deg (the horizontal part)
        Vec3 n = new Vec3(0, Math.cos(Math.toRadians(60)), Math.sin(Math.toRadians(60)));
        Vec3 between = handsim.math.Quat.fromAxisAngle(n, step).rotate(Vec3.X);
        assertEquals(step * Math.sin(Math.toRadians(60)), EndOverEnd.net(EndOverEnd.step(Vec3.X, between), up), 1e-9);
        // a turn and its way back cancel: the count is net, not a path length
        Vec3 there = EndOverEnd.step(Vec3.X, tipped), back = EndOverEnd.step(tipped, Vec3.X);
        assertEquals(0, EndOverEnd.net(there.plus(back), up), 1e-12);
        // the same weighting for rates: 5 rad/s about the horizontal z turns the x axis end over end
        // at 5 rad/s; about the vertical or about the axis itself not at all; about n, 5 sin 60 deg
        assertEquals(5, EndOverEnd.rate(new Vec3(0, 0, 5), Vec3.X, up), 1e-12);
        assertEquals(0, EndOverEnd.rate(new Vec3(0, 5, 0), Vec3.X, up), 1e-12);
        assertEquals(0, EndOverEnd.rate(new Vec3(5, 0, 0), Vec3.X, up), 1e-12);
        assertEquals(5 * Math.sin(Math.toRadians(60)), EndOverEnd.rate(n.times(5), Vec3.X, up), 1e-9);
    }

    /** The controller period: the episode shows the tracker one observation per 2 ms (configs/controller.json). */
    private static final double TICK = 0.002;

    /**
     * The net end-over-end turn a {@link FlightTracker} counts for a scripted flight: released at
     * t = 0 with the long axis at {@code axisAt.apply(0)}, followed every tick for {@code seconds}.
     */
    private static double trackedTurn(java.util.function.DoubleFunction<Vec3> axisAt, double seconds) {
        FlightTracker f = new FlightTracker(Vec3.Y);
        Vec3 rising = new Vec3(0, 2, 0);
        f.observe(true, true, Vec3.ZERO, rising, axisAt.apply(0), Vec3.ZERO); // held as the throw begins
        int ticks = (int) Math.round(seconds / TICK);
        for (int k = 0; k <= ticks; k++) {
            f.observe(false, true, Vec3.ZERO, rising, axisAt.apply(k * TICK), Vec3.ZERO);
        }
        return f.rotation();
    }

    @Test
    void aWobbleIsNoFlip() {
        // the long axis 30 deg above the horizontal, swept round the vertical at 3 rev/s for 0.6 s:
        // 1.8 sweeps of a tilted axis. Summed as a path (each tick's turn weighted by how
        // horizontal its axis is) it reads 281 deg, a can flip; the net turn about a horizontal axis
        // is sin(2e) |sin(pi n)| = sin 60 deg sin(0.2 pi) = 0.509 rad (29 deg) for e = 30 deg and
        // n = 1.8 sweeps (the horizontal turn axis sweeps round with the axis and cancels itself)
        double e = Math.toRadians(30), rate = 3 * 2 * Math.PI;
        double turn = trackedTurn(t -> new Vec3(Math.cos(e) * Math.cos(rate * t), Math.sin(e), Math.cos(e) * Math.sin(rate * t)), 0.6);
        assertEquals(Math.sin(2 * e) * Math.abs(Math.sin(Math.PI * 1.8)), turn, 0.01, "the closed form, to the ticks' chord error");
        assertEquals(0, can.flips(flight(Math.toDegrees(turn), true, target)), "a wobble is no can flip");
        assertEquals(0, club.flips(flight(Math.toDegrees(turn), true, target)));
    }

    @Test
    void aFlatSpinIsNoFlip() {
        // the long axis horizontal, spun about the vertical like a propeller at 20 rad/s for 0.6 s (nearly 2 turns)
        double turn = trackedTurn(t -> new Vec3(Math.cos(20 * t), 0, Math.sin(20 * t)), 0.6);
        assertEquals(0, turn, 1e-9, "every tick turns about the vertical");
        assertEquals(0, can.flips(flight(Math.toDegrees(turn), true, target)));
    }

    @Test
    void aCleanHalfTurnIsOneCanFlip() {
        // end over end about the horizontal z axis at pi / 0.5 s: half a turn in 0.5 s of flight
        double turn = trackedTurn(t -> rotatedAboutZ(Math.PI * t / 0.5), 0.5);
        assertEquals(Math.PI, turn, 1e-9);
        assertEquals(1, can.flips(flight(Math.toDegrees(turn), true, target)), "end for end is the same can");
        assertEquals(0, club.flips(flight(Math.toDegrees(turn), true, target)), "the club's handle points away");
    }

    @Test
    void aCleanWholeTurnIsOneClubFlip() {
        // end over end about a horizontal axis 40 deg off z (any horizontal axis counts alike): a whole turn in 0.6 s
        Vec3 axis = new Vec3(Math.sin(Math.toRadians(40)), 0, Math.cos(Math.toRadians(40)));
        Vec3 start = axis.cross(Vec3.Y); // horizontal, square to the turn axis
        double turn = trackedTurn(t -> handsim.math.Quat.fromAxisAngle(axis, 2 * Math.PI * t / 0.6).rotate(start), 0.6);
        assertEquals(2 * Math.PI, turn, 1e-9);
        assertEquals(1, club.flips(flight(Math.toDegrees(turn), true, target)), "the handle comes back to the hand");
        assertEquals(2, can.flips(flight(Math.toDegrees(turn), true, target)), "two half turns of a can");
    }

    @Test
    void theFlightRunsFromTheLastTouchOnTheWayUpToTheFirstOnTheWayDown() {
        FlightTracker f = new FlightTracker(Vec3.Y);
        Vec3 rising = new Vec3(0, 2, 0), falling = new Vec3(0, -2, 0), p = Vec3.ZERO;
        double step = Math.toRadians(10);
        Vec3 spin = new Vec3(0, 0, 12); // 12 rad/s about the horizontal z axis: end over end
        f.reset();
        f.observe(true, false, p, rising, rotatedAboutZ(0), spin); // held, throw not begun
        f.observe(false, false, p, rising, rotatedAboutZ(0), spin); // no contact for a tick before the throw: no release
        assertEquals(0, f.rotation(), 0);
        assertTrue(Double.isNaN(f.releaseSpin()), "no release yet");
        // released, turns 30 deg, then the rising hand meets it again: that turn was part of the throw
        for (int k = 0; k <= 3; k++) {
            f.observe(false, true, p, rising, rotatedAboutZ(k * step), spin);
        }
        assertEquals(3 * step, f.rotation(), 1e-9);
        assertEquals(12, f.releaseSpin(), 1e-9, "the spin as it left the hand");
        f.observe(true, true, p, rising, rotatedAboutZ(3 * step), spin);
        assertEquals(null, f.catchPoint(), "a touch on the way up is no catch");
        // released again: 18 ticks of 10 deg (a half turn), over the apex, caught on the way down
        for (int k = 3; k <= 21; k++) {
            f.observe(false, true, p, k < 12 ? rising : falling, rotatedAboutZ(k * step), spin.times(0.75));
        }
        assertEquals(9, f.releaseSpin(), 1e-9, "the spin of the last release");
        Vec3 caughtAt = new Vec3(0, 0.8, 0.3);
        f.observe(true, true, caughtAt, falling, rotatedAboutZ(21 * step), spin);
        assertEquals(Math.PI, f.rotation(), 1e-9, "only the turn since the last release counts");
        assertEquals(caughtAt, f.catchPoint());
        // the axis at 210 deg from the horizontal x stands 30 deg out of the horizontal as it arrives
        assertEquals(Math.toRadians(30), f.arrivalTilt(), 1e-9);
        // after the catch nothing more is counted
        f.observe(false, true, p, falling, rotatedAboutZ(30 * step), spin);
        assertEquals(Math.PI, f.rotation(), 1e-9);
        assertEquals(Math.toRadians(30), f.arrivalTilt(), 1e-9, "the first touch only");
        f.reset();
        assertTrue(Double.isNaN(f.arrivalTilt()), "a new throw has not arrived");
    }

    private static Vec3 rotatedAboutZ(double angle) {
        return new Vec3(Math.cos(angle), Math.sin(angle), 0);
    }

    @Test
    void aClosedLoopReleaseIsSetPerObjectAndABadOneIsNamed() throws Exception {
        ControllerConfig base = ControllerConfig.load(Home.resolve("configs/controller.json"));
        assertTrue(can.controller(base).release().isEmpty(), "the shipped flip config lets go on time, as the paper");
        ObjectNode root = (ObjectNode) Json.mapper().readTree(Files.readString(Home.resolve("configs/tasks/flip.json")));
        ObjectNode release = ((ObjectNode) root.at("/objects/can")).putObject("release");
        release.put("predictedTurnDeg", 270).put("earliest", 0.15).put("extension", 0.04);
        FlipTask withRelease = new FlipTask(FlipTask.Config.parse(Json.of("flip.json", root)), "can", TestSupport.neutralPalm());
        ClosedLoopRelease r = withRelease.controller(base).release().orElseThrow();
        assertEquals(new ClosedLoopRelease(Math.toRadians(270), 0.15, 0.04), r);
        assertTrue(new FlipTask(FlipTask.Config.parse(Json.of("flip.json", root)), "club", TestSupport.neutralPalm())
                .controller(base).release().isEmpty(), "per object: the club has none");
        release.put("predictedTurnDeg", 0);
        ConfigException e = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(e.getMessage().contains("predictedTurnDeg"), e.getMessage());
        release.put("predictedTurnDeg", 270).put("earliest", 0.5); // THROW lasts 0.2 s
        FlipTask late = new FlipTask(FlipTask.Config.parse(Json.of("flip.json", root)), "can", TestSupport.neutralPalm());
        IllegalArgumentException tooLate = assertThrows(IllegalArgumentException.class, () -> late.controller(base));
        assertTrue(tooLate.getMessage().contains("earliest"), tooLate.getMessage());
    }

    @Test
    void anArmRestIsSetPerObjectAndABadOneIsNamed() throws Exception {
        ControllerConfig base = ControllerConfig.load(Home.resolve("configs/controller.json"));
        ArmRest rest = can.controller(base).armRest().orElseThrow();
        assertEquals(0.01, rest.gain(), "configs/tasks/flip.json objects.can.armRest");
        assertEquals(java.util.Set.of(Phase.GOBACK, Phase.MIDDLE), rest.phases(), "drawn while the arm goes back and holds the can");
        assertEquals(-21.4, rest.jointsDeg().get("shoulder_abduction"), 1e-12);
        double[] posture = rest.chainVector(TestSupport.model(), new int[] {0, 1, 2, 3, 4, 5, 6});
        assertEquals(Math.toRadians(-21.4), posture[1], 1e-12, "shoulder_abduction is the chain's second DOF");
        assertEquals(Math.toRadians(-26.0), posture[6], 1e-12, "wrist_deviation its last");
        java.util.Map<String, Double> reversed = new java.util.LinkedHashMap<>();
        new java.util.ArrayDeque<>(rest.jointsDeg().keySet()).descendingIterator().forEachRemaining(k -> reversed.put(k, rest.jointsDeg().get(k)));
        assertArrayEquals(posture, new ArmRest(reversed, rest.gain(), rest.phases()).chainVector(TestSupport.model(), new int[] {0, 1, 2, 3, 4, 5, 6}),
                "in the chain's order whatever the file's");
        assertEquals(ArmRest.parse(Json.of("saved", rest.toJson())), rest, "toJson gives it back");
        assertTrue(new FlipTask(FlipTask.Config.parse(Json.load(Home.resolve("configs/tasks/flip.json"))), "club",
                TestSupport.neutralPalm()).controller(base).armRest().isEmpty(), "per object: the club has none");

        ObjectNode root = (ObjectNode) Json.mapper().readTree(Files.readString(Home.resolve("configs/tasks/flip.json")));
        ObjectNode armRest = (ObjectNode) root.at("/objects/can/armRest");
        armRest.put("gain", 0);
        ConfigException badGain = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(badGain.getMessage().contains("gain") && badGain.getMessage().contains("got 0"), badGain.getMessage());
        armRest.put("gain", 0.01);
        ((com.fasterxml.jackson.databind.node.ArrayNode) armRest.get("phases")).add("BREAK");
        ConfigException badPhase = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(badPhase.getMessage().contains("phases") && badPhase.getMessage().contains("BREAK"), badPhase.getMessage());
        armRest.putArray("phases");
        ConfigException noPhase = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(noPhase.getMessage().contains("phases"), noPhase.getMessage());
        armRest.putArray("phases").add("GOBACK");
        ObjectNode joints = (ObjectNode) armRest.get("jointsDeg");
        int[] chain = {0, 1, 2, 3, 4, 5, 6};
        joints.put("index_mcp_flexion", 10); // a finger's DOF is not the arm's
        ArmRest finger = ArmRest.parse(Json.of("flip.json", armRest));
        IllegalArgumentException notChain = assertThrows(IllegalArgumentException.class,
                () -> finger.chainVector(TestSupport.model(), chain));
        assertTrue(notChain.getMessage().contains("index_mcp_flexion"), notChain.getMessage());
        joints.remove("index_mcp_flexion");
        joints.remove("wrist_deviation");
        ArmRest missing = ArmRest.parse(Json.of("flip.json", armRest));
        IllegalArgumentException lacks = assertThrows(IllegalArgumentException.class,
                () -> missing.chainVector(TestSupport.model(), chain));
        assertTrue(lacks.getMessage().contains("wrist_deviation"), lacks.getMessage());
        joints.put("wrist_deviation", -40); // the model's range is [-30, 20]
        ArmRest beyond = ArmRest.parse(Json.of("flip.json", armRest));
        IllegalArgumentException outside = assertThrows(IllegalArgumentException.class,
                () -> beyond.chainVector(TestSupport.model(), chain));
        assertTrue(outside.getMessage().contains("wrist_deviation") && outside.getMessage().contains("-40"), outside.getMessage());
    }

    @Test
    void aCatchAfterEachFlipIsSetPerObjectAndABadOneIsNamed() throws Exception {
        ControllerConfig base = ControllerConfig.load(Home.resolve("configs/controller.json"));
        // the shipped can is caught level and turned (configs/tasks/flip.json), the club as the controller catches
        assertEquals(new CatchStyle(0, 0.7, new CatchStyle.Level(0.15, 0, 0.01, Math.toRadians(15), Math.toRadians(143),
                Math.toRadians(25)), new Vec3(0, 0, -0.0075)), can.controller(base).catchAfterThrow().orElseThrow());
        ObjectNode root = (ObjectNode) Json.mapper().readTree(Files.readString(Home.resolve("configs/tasks/flip.json")));
        ObjectNode level = ((ObjectNode) root.at("/objects/can/catch/level")).put("step", 0);
        ConfigException badLevel = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(badLevel.getMessage().contains("step") && badLevel.getMessage().contains("0"), badLevel.getMessage());
        level.put("step", 0.01).put("minTurnDeg", -10);
        ConfigException badTurn = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(badTurn.getMessage().contains("minTurnDeg") && badTurn.getMessage().contains("-10"), badTurn.getMessage());
        level.put("minTurnDeg", 140).put("turnTiltDeg", 10); // less than tiltDeg 15
        ConfigException badTurnTilt = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(badTurnTilt.getMessage().contains("turnTiltDeg") && badTurnTilt.getMessage().contains("10"),
                badTurnTilt.getMessage());
        level.remove("minTurnDeg");
        level.put("turnTiltDeg", 25); // without the turn it goes with
        ConfigException lone = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(lone.getMessage().contains("turnTiltDeg") && lone.getMessage().contains("minTurnDeg"), lone.getMessage());
        level.put("minTurnDeg", 143);
        ((ObjectNode) root.at("/objects/can/catch")).putArray("offset").add(0).add(0).add(-0.05);
        ConfigException badOffset = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(badOffset.getMessage().contains("offset") && badOffset.getMessage().contains("0.05"), badOffset.getMessage());
        ((ObjectNode) root.at("/objects/can")).putObject("catch").put("planeShift", 0.1).put("velocityFraction", 0.45);
        ControllerConfig flipping = new FlipTask(FlipTask.Config.parse(Json.of("flip.json", root)), "can", TestSupport.neutralPalm())
                .controller(base);
        assertEquals(new CatchStyle(0.1, 0.45), flipping.catchAfterThrow().orElseThrow());
        assertEquals(base.catchStyle(), flipping.catchStyle(), "the throw-in is still caught as the controller's own");
        ((ObjectNode) root.at("/objects/can/catch")).put("velocityFraction", 1.5);
        ConfigException e = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(e.getMessage().contains("velocityFraction") && e.getMessage().contains("1.5"), e.getMessage());
    }

    /**
     * The rest read from a decision's observation: the long axis's tilt out of the palm's plane
     * (palm y: its normal) and heading from across it (palm z), in a palm turned 30 deg about its
     * normal so that the palm's frame, not the world's, decides; the thresholds are FLAT_REST and
     * ASKEW_REST.
     */
    @Test
    void theRestAtADecisionIsReadInThePalmsFrame() {
        handsim.math.Quat palmTurn = handsim.math.Quat.fromAxisAngle(new Vec3(0, 1, 0), Math.toRadians(30));
        handsim.kin.Frame palm = new handsim.kin.Frame(Vec3.ZERO, palmTurn);
        Vec3 longAxis = new Vec3(0, 0, 1); // the can's, in its own frame
        FlipTask.Rest[] expected = {FlipTask.Rest.FLAT_ACROSS, FlipTask.Rest.FLAT_ASKEW, FlipTask.Rest.RAISED_ACROSS,
                FlipTask.Rest.RAISED_ASKEW};
        double[][] tiltHeadingDeg = {{3, 2}, {3, 20}, {25, 2}, {25, 20}};
        for (int i = 0; i < expected.length; i++) {
            double tilt = Math.toRadians(tiltHeadingDeg[i][0]), heading = Math.toRadians(tiltHeadingDeg[i][1]);
            // in the palm: x toward the fingers, y its normal, z across it
            Vec3 inPalm = new Vec3(Math.cos(tilt) * Math.sin(heading), Math.sin(tilt), Math.cos(tilt) * Math.cos(heading));
            handsim.math.Quat can = handsim.math.Quat.between(longAxis, palmTurn.rotate(inPalm));
            handsim.control.Observation at = new handsim.control.Observation(0, new double[0], new double[0], palm, Vec3.ZERO,
                    new handsim.sim.RigidState(Vec3.ZERO, can, Vec3.ZERO, Vec3.ZERO), 0);
            LyingPose pose = LyingPose.of(palm, can.rotate(longAxis));
            assertEquals(tilt, pose.tilt(), 1e-9, "tilt " + i);
            assertEquals(heading, pose.heading(), 1e-9, "heading " + i);
            assertEquals(expected[i], FlipTask.Rest.at(at, longAxis), "rest " + i);
        }
        assertEquals(FlipTask.Rest.FLAT_ASKEW, FlipTask.Rest.ofLabel("flat_askew"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> FlipTask.Rest.ofLabel("flat"));
        assertTrue(e.getMessage().contains("\"flat\"") && e.getMessage().contains("flat_askew"), e.getMessage());
    }
}
