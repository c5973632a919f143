package handsim.export;

import handsim.model.HandModel;
import handsim.sim.WorldSnapshot;
import handsim.task.Goal;
import java.util.ArrayList;
import java.util.List;

/**
 * Samples a run's snapshots {@code rate} times a simulated second into a {@link MotionClip}. It
 * is offered snapshots as often as its owner has them (every controller tick of a headless run,
 * every frame the viewer draws) and keeps the first at or after each sample time. Its clock is
 * the simulated time, carried on across resets of the world (a new episode starts the
 * simulator's clock at 0; the recording's goes on), so sample times always increase.
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

    /** Keeps {@code snapshot} if a sample is due at its time; {@code goal} is the task's goal then. */
    public void offer(WorldSnapshot snapshot, Goal goal) {
        if (due(snapshot.time())) {
            record(snapshot, goal);
        }
    }

    /** Keeps {@code snapshot} (its time given to {@link #due} just before) as the next sample. */
    public void record(WorldSnapshot snapshot, Goal goal) {
        if (Double.isNaN(start)) {
            start = elapsed();
            model = snapshot.model();
            groundHeight = snapshot.groundHeight();
        }
        samples.add(MotionClip.Sample.of(elapsed() - start, snapshot, goal));
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

    /** When the next sample is due: the first grid time k / rate after the last sample's. */
    private double nextTime() {
        double last = samples.get(samples.size() - 1).time();
        long k = (long) Math.floor(last * rate + TIME_EPSILON) + 1;
        return start + k * period;
    }
}
