package handsim.task;

import java.util.SplittableRandom;

/**
 * The desired apex height of each throw (the height task's config says which heights a goal may
 * have, {@link HeightTask.Config#allowsGoal}): fixed, drawn uniformly from [low, high] for every
 * throw from the episode's seed, or taken in turn from a given list (again from its start in
 * every episode). The policy reads {@link #current()}; the episode moves on to
 * the next goal once a throw has been made. A person watching may {@link #shift} the goals up or
 * down while the episode runs.
 */
public final class HeightGoals {

    private double low;
    private double high;
    private SplittableRandom rng = new SplittableRandom(0);
    private double current;
    private double[] sequence;
    private int next;

    public HeightGoals(double low, double high) {
        if (!(low > 0 && high >= low && high < Double.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("height goals must lie above 0 m with low <= high, got [" + low + ", " + high + "]");
        }
        this.low = low;
        this.high = high;
        this.current = low;
    }

    /** The heights of {@code list} in turn, one per throw (cycling through it in a long episode). */
    public static HeightGoals sequence(double[] list) {
        if (list.length == 0) {
            throw new IllegalArgumentException("a list of height goals needs at least one height");
        }
        double lo = java.util.Arrays.stream(list).min().orElseThrow(), hi = java.util.Arrays.stream(list).max().orElseThrow();
        HeightGoals g = new HeightGoals(lo, hi);
        g.sequence = list.clone();
        return g;
    }

    /** One height for every throw. */
    public static HeightGoals fixed(double height) {
        return new HeightGoals(height, height);
    }

    /** Starts the goal sequence of an episode and draws its first goal. */
    public void reset(long seed) {
        rng = new SplittableRandom(seed ^ 0x9E3779B97F4A7C15L);
        next = 0;
        advance();
    }

    /** The goal of the next (or current) throw (m, world). */
    public double current() {
        return current;
    }

    /** Moves the range and the current goal by {@code dy} metres; the range stays above 0. */
    public void shift(double dy) {
        if (!(low + dy > 0)) {
            throw new IllegalArgumentException("height goals must stay above 0 m, got a shift of " + dy + " from " + low);
        }
        low += dy;
        high += dy;
        current += dy;
        if (sequence != null) {
            for (int i = 0; i < sequence.length; i++) {
                sequence[i] += dy;
            }
        }
    }

    void advance() {
        if (sequence != null) {
            current = sequence[next++ % sequence.length];
        } else {
            current = high > low ? low + (high - low) * rng.nextDouble() : low;
        }
    }

    public double low() {
        return low;
    }

    public double high() {
        return high;
    }
}
