package handsim.evaluation;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.math.Vec3;
import handsim.task.FlipTask;
import handsim.task.LoopRecord;
import handsim.task.Rest;
import handsim.task.ScriptedLoops;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The counts of the flip report on scripted throws of the can (configs/tasks/flip.json's flip task). */
@Tag("fast")
class FlipReportTest {

    private final FlipTask can = TestSupport.configs().flip().newTask("can");
    private final Vec3 target = TestSupport.neutralPalm().plus(new Vec3(0, 0.12, 0));
    /** The bins of configs/evaluation.json's flipBins: 15 deg, throws 2-5 early, edges 4 and 8 cm. */
    private static final FlipReport.Bins BINS = new FlipReport.Bins(Math.toRadians(15), 5, new double[] {0.04, 0.08});
    private final FlipReport report = new FlipReport(can, BINS);

    @Test
    void throwsAreBinnedByFlightRotationInQuarterFlips() {
        // can: quarters of its 180 deg flip, 45 deg wide; the throw-in and a throw with no measured flight are left out
        LoopRecord throwIn = new LoopRecord(0, true, Double.NaN, null, Double.NaN, null, false, Double.NaN, Double.NaN,
                Double.NaN, Double.NaN, Double.NaN, null, Double.NaN, 0, 0, 0, 1);
        var bins = report.byFlightRotation(List.of(throwIn, ScriptedLoops.flight(10, true, target), ScriptedLoops.flight(200, true, target),
                ScriptedLoops.flight(210, true, target), ScriptedLoops.flight(220, false, target), ScriptedLoops.flight(Double.NaN, true, target)));
        assertEquals(5, bins.size(), "0-45 up to 180-225, the empty bins between included");
        assertEquals(Math.toRadians(180), bins.get(4).from(), 1e-12);
        assertEquals(Math.toRadians(225), bins.get(4).to(), 1e-12);
        assertEquals(1, bins.get(0).throwsMade());
        assertEquals(0, bins.get(0).successes(), "10 deg is no flip");
        assertEquals(0, bins.get(2).throwsMade());
        assertEquals(3, bins.get(4).throwsMade());
        assertEquals(2, bins.get(4).successes(), "the dropped one is no success");
        assertTrue(report.byFlightRotation(List.of(throwIn)).isEmpty());
    }


    @Test
    void throwsAreBinnedByHowFarTheAxisStoodOutOfTheHorizontalWhenTheObjectCameBack() {
        // six 15 deg bins from lying (0) to end-first (90), empty ones included; a throw that never came back
        // to the hand (NaN) and the throw-in are left out
        LoopRecord throwIn = new LoopRecord(0, true, Double.NaN, null, Double.NaN, null, false, Double.NaN, Double.NaN,
                Double.NaN, Double.NaN, Double.NaN, null, Math.toRadians(10), 0, 0, 0, 1);
        var bins = report.byArrivalTilt(List.of(throwIn, ScriptedLoops.arriving(5, true, 10), ScriptedLoops.arriving(14, false, 0), ScriptedLoops.arriving(70, true, 80),
                ScriptedLoops.arriving(89, false, 0), ScriptedLoops.arriving(90, true, 85), ScriptedLoops.arriving(Double.NaN, false, 0)));
        assertEquals(6, bins.size());
        assertEquals(Math.toRadians(75), bins.get(5).from(), 1e-12);
        assertEquals(Math.toRadians(90), bins.get(5).to(), 1e-12);
        assertEquals(new FlipReport.ArrivalBin(0, Math.toRadians(15), 2, 1, 1, 0), bins.get(0), "a flip caught lying, a drop");
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
        assertEquals(java.util.Optional.empty(), can.failure(ScriptedLoops.arriving(10, true, 10)), "flipped (180 deg) and caught lying");
        assertEquals(FlipTask.Failure.ARRIVED_END_FIRST, can.failure(ScriptedLoops.arriving(70, true, 80)).orElseThrow());
        assertEquals(FlipTask.Failure.ARRIVED_END_FIRST, can.failure(ScriptedLoops.arriving(60, false, 0)).orElseThrow(), "60 deg is end-first");
        assertEquals(FlipTask.Failure.DROPPED, can.failure(ScriptedLoops.arriving(59, false, 0)).orElseThrow());
        assertEquals(FlipTask.Failure.DROPPED, can.failure(ScriptedLoops.flight(180, false, target)).orElseThrow(), "never came back (NaN)");
        assertEquals(FlipTask.Failure.CAUGHT_STANDING, can.failure(ScriptedLoops.arriving(40, true, 50)).orElseThrow());
        assertEquals(FlipTask.Failure.NO_FLIP, can.failure(ScriptedLoops.flight(90, true, target, 10)).orElseThrow());
        LoopRecord throwIn = new LoopRecord(0, true, Double.NaN, null, Double.NaN, null, false, Double.NaN, Double.NaN,
                Double.NaN, Double.NaN, Double.NaN, null, Double.NaN, 0, 0, 0, 1);
        FlipReport.ThrowTally t = report.tally(List.of(throwIn, ScriptedLoops.arriving(10, true, 10), ScriptedLoops.arriving(70, true, 80), ScriptedLoops.arriving(59, false, 0),
                ScriptedLoops.flight(90, true, target, 10), ScriptedLoops.arriving(5, true, 20)));
        assertEquals(5, t.throwsMade(), "the throw-in is no throw");
        assertEquals(2, t.successes());
        assertEquals(0.4, t.successRate(), 1e-12);
        assertEquals(java.util.Map.of(FlipTask.Failure.ARRIVED_END_FIRST, 1, FlipTask.Failure.DROPPED, 1,
                FlipTask.Failure.CAUGHT_STANDING, 0, FlipTask.Failure.NO_FLIP, 1), t.failures());
    }

    @Test
    void firstThrowsAreBinnedByTheHeadingTheThrowInRestedAt() {
        // six 15-degree bins from 0 (across the palm) to 90 (along the fingers); 90 itself falls in the last
        List<FlipReport.AngleBin> bins = report.firstThrowsByRestHeading(List.of(
                List.of(ScriptedLoops.restingAt(5), ScriptedLoops.flight(180, true, target)),
                List.of(ScriptedLoops.restingAt(10), ScriptedLoops.flight(90, true, target), ScriptedLoops.flight(180, true, target)),
                List.of(ScriptedLoops.restingAt(50), ScriptedLoops.flight(180, true, target)),
                List.of(ScriptedLoops.restingAt(90), ScriptedLoops.flight(180, false, target)),
                List.of(ScriptedLoops.restingAt(Double.NaN)),
                List.of(ScriptedLoops.restingAt(20))));
        assertEquals(6, bins.size());
        assertEquals(Math.toRadians(45), bins.get(3).from(), 1e-12);
        assertEquals(Math.toRadians(60), bins.get(3).to(), 1e-12);
        int[] made = bins.stream().mapToInt(FlipReport.AngleBin::throwsMade).toArray();
        int[] succeeded = bins.stream().mapToInt(FlipReport.AngleBin::successes).toArray();
        // only loop 1 counts (episode 2's second throw is left out); a dropped throw-in or one not thrown from is no first throw
        assertArrayEquals(new int[] {2, 0, 0, 1, 0, 1}, made);
        assertArrayEquals(new int[] {1, 0, 0, 1, 0, 0}, succeeded);
    }

    @Test
    void laterThrowsAreCountedByTheRestTheCatchBeforeThemLeft() {
        // flat: under 10 deg out of the palm's plane; askew: 5 deg or more from across the palm
        // (Rest.FLAT_TILT, ASKEW_HEADING); throws 2-5 are early, from the 6th later; the first
        // throw (from the throw-in) is not counted, nor a throw after a catch with no tilt measured
        LoopRecord raisedAcross = ScriptedLoops.caughtResting(15, 2, target), flatAskew = ScriptedLoops.caughtResting(5, 8, target), flatAcross = ScriptedLoops.caughtResting(9.9, 4.9, target),
                raisedAskew = ScriptedLoops.caughtResting(10, 5, target), dropped = ScriptedLoops.flight(180, false, target), failed = ScriptedLoops.flight(90, true, target, 10);
        List<LoopRecord> episode = List.of(ScriptedLoops.restingAt(0), raisedAcross, flatAskew, failed);
        List<LoopRecord> longer = List.of(ScriptedLoops.restingAt(0), flatAskew, raisedAcross, dropped, raisedAskew, flatAcross, flatAskew,
                raisedAcross);
        List<FlipReport.RestCount> counts = report.laterThrowsByRest(List.of(episode, longer));
        assertEquals(List.of(Rest.values()), counts.stream().map(FlipReport.RestCount::rest).toList(), "all four rests, in order");
        // episode: throw 2 from raised-across succeeds, throw 3 from flat-askew fails (no flip);
        // longer: throw 2 from flat-askew succeeds, 3 from raised-across is dropped, 4 follows the drop
        // (no rest: left out), 5 from raised-askew (10 deg is not flat, 5 deg is askew) succeeds,
        // 6 from flat-across (9.9, 4.9 deg) and 7 from flat-askew succeed as later throws
        assertEquals(List.of(new FlipReport.ThrowsAfter(2, 1, 0, 0), new FlipReport.ThrowsAfter(1, 1, 0, 0), new FlipReport.ThrowsAfter(0, 0, 1, 1),
                new FlipReport.ThrowsAfter(2, 1, 1, 1)), counts.stream().map(FlipReport.RestCount::throwsAfter).toList());
    }

    @Test
    void laterThrowsAreCountedByHowFarFromTheRunsMedianCatchTheCatchBeforeThemWas() {
        // a flip caught at target + (dx, dy, dz); the median of the hand's catches is the target
        // (x offsets 0 0 0 0 0 .01 .10 and z 0 ... .05: medians 0); only the horizontal distance
        // counts (BINS: under 4 cm, 4-8 cm, 8 cm and over); throws 2-5
        // are early, from the 6th later; the throw after a drop (no catch point) is left out
        LoopRecord near = ScriptedLoops.flight(180, true, target), raisedBeside = ScriptedLoops.flight(180, true, target.plus(new Vec3(0.01, 0.3, 0))),
                mid = ScriptedLoops.flight(180, true, target.plus(new Vec3(0, 0, 0.05))), far = ScriptedLoops.flight(180, true, target.plus(new Vec3(0.10, 0, 0))),
                failed = ScriptedLoops.flight(90, true, target), dropped = ScriptedLoops.flight(180, false, target);
        List<LoopRecord> episode = List.of(ScriptedLoops.restingAt(0), near, raisedBeside, mid, far, failed, near, dropped, near);
        FlipReport.CatchDistances d = report.laterThrowsByCatchDistance(List.of(episode)).orElseThrow();
        assertEquals(0, d.medianCatch().minus(target).norm(), 1e-12, "the median of each coordinate");
        assertEquals(List.of(new FlipReport.DistanceCount(0, 0.04, new FlipReport.ThrowsAfter(2, 2, 2, 1)),
                new FlipReport.DistanceCount(0.04, 0.08, new FlipReport.ThrowsAfter(1, 1, 0, 0)),
                new FlipReport.DistanceCount(0.08, Double.POSITIVE_INFINITY, new FlipReport.ThrowsAfter(1, 0, 0, 0))), d.bins());
        assertTrue(report.laterThrowsByCatchDistance(List.of(List.of(ScriptedLoops.restingAt(0)), List.of(ScriptedLoops.restingAt(Double.NaN)))).isEmpty(),
                "no catch of the hand's own: nothing to measure from");
    }
}
