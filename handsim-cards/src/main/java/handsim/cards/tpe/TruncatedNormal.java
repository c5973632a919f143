package handsim.cards.tpe;

import java.util.SplittableRandom;
import org.apache.commons.math3.special.Erf;

/**
 * The standard normal truncated to [a, b]: its log density, the log of the mass it keeps, and
 * sampling by inverting its CDF. Everything is computed in log space and in the left tail
 * (mirrored for the right one), as Optuna 3.6.1's {@code _truncnorm} does, so kernels whose
 * bounds lie 30 sigmas away still give finite, accurate log densities.
 */
final class TruncatedNormal {

    private static final double SQRT2 = Math.sqrt(2);
    private static final double LOG_SQRT_2PI = Math.log(Math.sqrt(2 * Math.PI));
    /** Most steps of the inverse CDF's search: bisection alone reaches a double's resolution in fewer. */
    private static final int MAX_STEPS = 200;

    private TruncatedNormal() {
    }

    /** Φ(a), the standard normal CDF, with erfc in the tails to keep its relative accuracy. */
    static double cdf(double a) {
        double x = a / SQRT2;
        if (x < -1 / SQRT2) {
            return 0.5 * Erf.erfc(-x);
        }
        if (x < 1 / SQRT2) {
            return 0.5 + 0.5 * Erf.erf(x);
        }
        return 1 - 0.5 * Erf.erfc(x);
    }

    /** log Φ(a); for a < -20 the asymptotic series of the Mills ratio. */
    static double logCdf(double a) {
        if (a > 6) {
            return -cdf(-a); // log(1 - ε) = -ε to double precision
        }
        if (a > -20) {
            return Math.log(cdf(a));
        }
        // log Φ(a) = -a²/2 - log(-a) - log √(2π) + log(1 - 1/a² + 1·3/a⁴ - 1·3·5/a⁶ + ...)
        double logLeading = -0.5 * a * a - Math.log(-a) - 0.5 * Math.log(2 * Math.PI);
        double previous = 0, sum = 1, numerator = 1, denominator = 1, sign = 1;
        for (int i = 1; Math.abs(previous - sum) > Math.ulp(1.0); i++) {
            previous = sum;
            sign = -sign;
            denominator *= 1 / (a * a);
            numerator *= 2 * i - 1;
            sum += sign * numerator * denominator;
        }
        return logLeading + Math.log(sum);
    }

    /** log of the standard normal's mass in [a, b], a <= b. */
    static double logMass(double a, double b) {
        if (b <= 0) {
            return logDiff(logCdf(b), logCdf(a));
        }
        if (a > 0) {
            return logMass(-b, -a); // right tail: mirror into the left one
        }
        return Math.log1p(-cdf(a) - cdf(-b)); // central: 1 minus both tails, no cancellation
    }

    /**
     * log density at x of N(loc, scale²) truncated to [loc + a·scale, loc + b·scale]; -∞
     * outside.
     */
    static double logPdf(double x, double a, double b, double loc, double scale) {
        return logPdf(x, a, b, loc, scale, logMass(a, b), Math.log(scale));
    }

    /** {@link #logPdf(double, double, double, double, double)} given logMass(a, b) and log(scale). */
    static double logPdf(double x, double a, double b, double loc, double scale, double logMass, double logScale) {
        double z = (x - loc) / scale;
        if (z < a || z > b) {
            return Double.NEGATIVE_INFINITY;
        }
        return -(z * z) / 2.0 - LOG_SQRT_2PI - logMass - logScale;
    }

    /** A draw from the standard normal truncated to [a, b] (inverse CDF at a uniform quantile). */
    static double sample(double a, double b, SplittableRandom rng) {
        return quantile(rng.nextDouble(), a, b);
    }

    /** The q-quantile of the standard normal truncated to [a, b], solved in the thinner tail. */
    static double quantile(double q, double a, double b) {
        if (q == 0) {
            return a;
        }
        if (a < 0) {
            // Φ(x) = Φ(a) + q·mass(a, b)
            return inverseLogCdf(logSum(logCdf(a), Math.log(q) + logMass(a, b)));
        }
        // Φ(-x) = Φ(-b) + (1 - q)·mass(a, b)
        return -inverseLogCdf(logSum(logCdf(-b), Math.log1p(-q) + logMass(a, b)));
    }

    /**
     * x with log Φ(x) = y in [-100, 100]: Newton's method on log Φ (slope φ/Φ), kept inside a
     * bisection bracket that every step narrows; a step leaving the bracket is a bisection.
     */
    private static double inverseLogCdf(double y) {
        double lo = -100, hi = 100, x = 0;
        for (int i = 0; i < MAX_STEPS; i++) {
            double logPhi = logCdf(x), f = logPhi - y;
            if (f == 0) {
                return x;
            }
            if (f < 0) {
                lo = x;
            } else {
                hi = x;
            }
            double slope = Math.exp(-0.5 * x * x - LOG_SQRT_2PI - logPhi);
            double next = x - f / slope;
            if (!(next > lo && next < hi)) {
                next = 0.5 * (lo + hi);
            }
            if (Math.abs(next - x) <= 1e-14 * Math.max(1, Math.abs(x))) {
                return next;
            }
            x = next;
        }
        return x;
    }

    private static double logSum(double logP, double logQ) {
        double max = Math.max(logP, logQ), min = Math.min(logP, logQ);
        return max == Double.NEGATIVE_INFINITY ? max : max + Math.log1p(Math.exp(min - max));
    }

    private static double logDiff(double logP, double logQ) {
        return logP + Math.log1p(-Math.exp(logQ - logP));
    }
}
