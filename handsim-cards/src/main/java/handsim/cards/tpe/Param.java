package handsim.cards.tpe;

import java.util.SplittableRandom;

/**
 * One dimension of a search space: a float or an integer in [low, high], searched on a linear
 * or a log scale (Optuna's {@code FloatDistribution} and {@code IntDistribution} without a
 * step, or with step 1 for integers). Values cross this API in their own units; integers as
 * whole doubles.
 *
 * <p>The Parzen estimators work in an internal coordinate: x, or log x on a log scale. Integers
 * on a linear scale are discrete kernels on the grid; integers on a log scale are continuous in
 * log x over [log(low - ½), log(high + ½)] and rounded afterwards, as Optuna 3.6.1 does.
 */
public record Param(String name, double low, double high, boolean log, boolean integer) {

    public Param {
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException("param name: must not be empty");
        }
        if (!Double.isFinite(low) || !Double.isFinite(high) || !(low < high)) {
            throw new IllegalArgumentException("param " + name + ": low must be < high (both finite), got [" + low + ", " + high + "]");
        }
        if (integer && (low != Math.rint(low) || high != Math.rint(high))) {
            throw new IllegalArgumentException("param " + name + ": an integer's low and high must be whole numbers, got [" + low + ", " + high + "]");
        }
        if (log && !(low > 0)) {
            throw new IllegalArgumentException("param " + name + ": a log-scale parameter needs low > 0, got " + low);
        }
    }

    /** A float searched linearly in [low, high]. */
    public static Param uniform(String name, double low, double high) {
        return new Param(name, low, high, false, false);
    }

    /** A float searched on a log scale in [low, high]. */
    public static Param logUniform(String name, double low, double high) {
        return new Param(name, low, high, true, false);
    }

    /** An integer in [low, high]. */
    public static Param integer(String name, int low, int high) {
        return new Param(name, low, high, false, true);
    }

    /** The internal coordinate of a value. */
    double toInternal(double value) {
        return log ? Math.log(value) : value;
    }

    /** The Parzen estimators' domain, low end (internal coordinate). */
    double internalLow() {
        return log ? Math.log(integer ? low - 0.5 : low) : low;
    }

    /** The Parzen estimators' domain, high end (internal coordinate). */
    double internalHigh() {
        return log ? Math.log(integer ? high + 0.5 : high) : high;
    }

    /** Grid step of discrete kernels: 1 for integers on a linear scale, 0 (continuous) otherwise. */
    double step() {
        return integer && !log ? 1 : 0;
    }

    /** A value from an internal coordinate: exp on a log scale, integers rounded into [low, high]. */
    double fromInternal(double internal) {
        double v = log ? Math.exp(internal) : internal;
        return integer ? roundToGrid(v) : v;
    }

    /**
     * A uniform random value, as Optuna's RandomSampler draws it: floats in [low, high), on a log
     * scale uniform in log x; integers uniform over [low - ½, high + ½] (in log x on a log scale)
     * and rounded.
     */
    double random(SplittableRandom rng) {
        if (integer) {
            double lo = log ? Math.log(low - 0.5) : low - 0.5, hi = log ? Math.log(high + 0.5) : high + 0.5;
            double u = uniform(lo, hi, rng);
            return roundToGrid(log ? Math.exp(u) : u);
        }
        double u = log ? Math.exp(uniform(Math.log(low), Math.log(high), rng)) : uniform(low, high, rng);
        return Math.min(u, Math.nextDown(high));
    }

    private static double uniform(double lo, double hi, SplittableRandom rng) {
        return lo + (hi - lo) * rng.nextDouble();
    }

    /** Nearest integer (ties to even, as numpy rounds), clipped into [low, high]. */
    private double roundToGrid(double v) {
        return Math.min(Math.max(low + Math.rint(v - low), low), high);
    }
}
