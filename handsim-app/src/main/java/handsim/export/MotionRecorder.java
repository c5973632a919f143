package handsim.export;

import handsim.model.HandModel;
import handsim.sim.WorldSnapshot;
import handsim.task.Goal;
import java.util.ArrayList;
import java.util.List;

/**
 * Samples a run's snapshots {@code rate} times a simulated second into a {@link MotionClip}, at
 * times as near the grid {@code k / rate} as the snapshots offered allow. Its clock is the
 * simulated time, carried on across resets of the world (a new episode starts the simulator's
 * clock at 0; the recording's goes on), so sample times always increase. Two ways in:
 * <ul>
 * <li>{@link #due} then {@link #record}, for an owner that makes a snapshot only when one is due
 * (a headless run's ticks): the first at or after each sample time is kept;
 * <li>{@link #offer}, for an owner that has every snapshot anyway (the viewer's frames, which
 * come at their own pace): of the snapshots around each sample time, the nearer is kept.
 * </ul>
 */
public final class MotionRecorder {

    /** Simulated time is a sum of steps: a sample time counts as reached this close (s). */
    static final double TIME_EPSILON = 1e-9;

    private final double rate;
    private final double period;
    private final List<MotionClip.Sample> samples = new ArrayList<>();
    private HandModel model;
    private double groundHeight;
    /** Recorded seconds before the current run of the simulator's clock (the sum over resets). */
    private double base;
    private double lastSimTime = Double.NaN;
    private double start = Double.NaN;
    /** The index k of the next sample time, start + k / rate. */
    private long slot;
    /** The last snapshot offered before the next sample time, with its goal and clock reading, or null. */
    private WorldSnapshot before;
    private Goal beforeGoal;
    private double beforeElapsed;

    /** A recorder of {@code rate} samples per simulated second. */
    public MotionRecorder(double rate) {
        if (!(rate > 0 && rate <= 1000)) {
            throw new IllegalArgumentException("a recording rate must be in (0, 1000] Hz, got " + rate);
        }
        this.rate = rate;
        this.period = 1 / rate;
    }

    /** Samples per simulated second. */
    public double rate() {
        return rate;
    }

    /** How many samples a recording of {@code seconds} holds: one at 0, then one every 1 / rate s. */
    public int samplesOver(double seconds) {
        return (int) Math.floor(seconds * rate + TIME_EPSILON) + 1;
    }

    /**
     * Moves the recording's clock to the simulator's time {@code simTime} (a time earlier than
     * the last means the world was reset) and says whether a sample is due.
     */
    public boolean due(double simTime) {
        if (!Double.isNaN(lastSimTime) && simTime < lastSimTime) {
            base += lastSimTime;
        }
        lastSimTime = simTime;
        return Double.isNaN(start) || elapsed() >= nextTime() - TIME_EPSILON;
    }

    /** Keeps {@code snapshot} (its time given to {@link #due} just before) as the next sample; {@code goal} is the task's goal then. */
    public void record(WorldSnapshot snapshot, Goal goal) {
        keep(snapshot, goal, elapsed());
    }

    /**
     * Offers {@code snapshot} (with the task's goal then): when it reaches the next sample time,
     * the nearer of it and the snapshot offered just before is kept.
     */
    public void offer(WorldSnapshot snapshot, Goal goal) {
        if (!due(snapshot.time())) {
            before = snapshot;
            beforeGoal = goal;
            beforeElapsed = elapsed();
            return;
        }
        double next = Double.isNaN(start) ? elapsed() : nextTime();
        if (before != null && next - beforeElapsed < elapsed() - next && beforeElapsed > lastSampleTime() + TIME_EPSILON) {
            keep(before, beforeGoal, beforeElapsed);
            before = null;
            if (!due(snapshot.time())) {
                before = snapshot;
                beforeGoal = goal;
                beforeElapsed = elapsed();
                return;
            }
        }
        before = null;
        record(snapshot, goal);
    }

    private void keep(WorldSnapshot snapshot, Goal goal, double at) {
        if (Double.isNaN(start)) {
            start = at;
            model = snapshot.model();
            groundHeight = snapshot.groundHeight();
        }
        samples.add(MotionClip.Sample.of(at - start, snapshot, goal));
        slot = Math.max(slot + 1, (long) Math.floor((at - start) * rate + TIME_EPSILON) + 1);
    }

    /** Simulated seconds from now until the next sample is due (0 before the first). */
    public double untilNext() {
        return Double.isNaN(start) ? 0 : Math.max(0, nextTime() - elapsed());
    }

    public int sampleCount() {
        return samples.size();
    }

    /** The samples so far as a clip named {@code title}. */
    public MotionClip clip(String title) {
        if (samples.isEmpty()) {
            throw new IllegalStateException("nothing recorded yet");
        }
        return new MotionClip(title, model, rate, groundHeight, samples);
    }

    /** The recording's clock: simulated seconds since the simulator's first reading. */
    private double elapsed() {
        return base + lastSimTime;
    }

    /** The recording's clock at the last sample. */
    private double lastSampleTime() {
        return start + samples.get(samples.size() - 1).time();
    }

    /** When the next sample is due: the grid time after the last sample's slot (and after the last sample). */
    private double nextTime() {
        return start + slot * period;
    }
}
