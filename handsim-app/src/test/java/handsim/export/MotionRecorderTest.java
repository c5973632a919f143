package handsim.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.kin.Frame;
import handsim.model.HandModel;
import handsim.sim.WorldSnapshot;
import handsim.task.Goal;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The recorder's clock: one sample per 1 / rate simulated seconds from the first, carried on over resets. */
@Tag("fast")
class MotionRecorderTest {

    static final HandModel MODEL = TestSupport.model();

    static WorldSnapshot at(double time) {
        return new WorldSnapshot(MODEL, time, Collections.nCopies(MODEL.bodyCount(), Frame.IDENTITY), Optional.empty(), Optional.empty(),
                List.of(), 0);
    }

    @Test
    void askedEveryTickItKeepsTheFirstAtOrAfterEachSampleTime() {
        MotionRecorder r = new MotionRecorder(60);
        // controller ticks of 2 ms (10 steps of 0.2 ms, summed as the simulator sums them)
        double t = 0;
        for (int tick = 0; tick <= 500; tick++) {
            if (r.due(t)) {
                r.record(at(t), new Goal.None());
            }
            for (int s = 0; s < 10; s++) {
                t += 2e-4;
            }
        }
        // 1 s at 60 Hz: samples at 0, 1/60, ..., 1 (61), each the first tick at or after its time
        MotionClip clip = r.clip("ticks");
        assertEquals(61, clip.samples().size());
        for (int k = 0; k < clip.samples().size(); k++) {
            double time = clip.samples().get(k).time();
            assertTrue(time >= k / 60.0 - 1e-9 && time < k / 60.0 + 0.002, "sample " + k + " at " + time);
        }
        assertEquals(61, r.samplesOver(1.0));
    }

    @Test
    void aResetOfTheWorldDoesNotTakeTheClockBack() {
        MotionRecorder r = new MotionRecorder(10);
        for (double t : new double[] {0, 0.1, 0.2, 0.25, 0.0, 0.05, 0.1}) {
            if (r.due(t)) {
                r.record(at(t), new Goal.None());
            }
        }
        // before the reset: 0, 0.1, 0.2 (0.25 is not due: the next sample is at 0.3); after it the
        // clock reads 0.25 + t: 0.3 at t = 0.05, then 0.35 (not due)
        List<MotionClip.Sample> s = r.clip("reset").samples();
        assertEquals(4, s.size());
        assertEquals(0.3, s.get(3).time(), 1e-12);
    }

    @Test
    void offeredFramesAtTheirOwnPaceItKeepsTheNearestToEachSampleTime() {
        MotionRecorder r = new MotionRecorder(60);
        // a viewer's frames: about 1/60 s apart, each a whole number of 2 ms ticks (16 or 18 ms)
        double[] frames = {0, 0.016, 0.034, 0.050, 0.066, 0.084, 0.100};
        for (double t : frames) {
            r.offer(at(t), new Goal.None());
        }
        // every grid time k/60 has a frame within 1 ms of it: each is kept, none twice
        List<MotionClip.Sample> s = r.clip("frames").samples();
        assertEquals(frames.length, s.size());
        for (int k = 0; k < s.size(); k++) {
            assertEquals(frames[k], s.get(k).time(), 1e-12);
        }
    }

    @Test
    void aRateOutOfRangeIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> new MotionRecorder(0));
        assertThrows(IllegalArgumentException.class, () -> new MotionRecorder(Double.NaN));
    }
}
