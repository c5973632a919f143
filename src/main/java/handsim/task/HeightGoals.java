package handsim.task;

import java.util.SplittableRandom;

/**
 * The desired apex height of each throw: fixed, or drawn uniformly from [low, high] for every
 * throw from the episode's seed. The policy reads {@link #current()}; the episode moves on to
 * the next goal once a throw has been made.
 */
public final class HeightGoals {

    private final double low;
    private final double high;
    private SplittableRandom rng = new SplittableRandom(0);
    private double current;

    public HeightGoals(double low, double high) {
        if (!(low > 0 && high >= low)) {
            throw new IllegalArgumentException("height goals need 0 < low <= high, got [" + low + ", " + high + "]");
        }
        this.low = low;
        this.high = high;
        this.current = low;
    }

    /** One height for every throw. */
    public static HeightGoals fixed(double height) {
        return new HeightGoals(height, height);
    }

    /** Starts the goal sequence of an episode and draws its first goal. */
    public void reset(long seed) {
        rng = new SplittableRandom(seed ^ 0x9E3779B97F4A7C15L);
        advance();
    }

    /** The goal of the next (or current) throw (m, world). */
    public double current() {
        return current;
    }

    void advance() {
        current = high > low ? low + (high - low) * rng.nextDouble() : low;
    }

    public double low() {
        return low;
    }

    public double high() {
        return high;
    }
}
