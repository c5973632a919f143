package handsim.cards.tpe;

import java.util.Arrays;
import java.util.Comparator;
import java.util.SplittableRandom;
import java.util.stream.IntStream;

/**
 * One parameter's Parzen estimator, l(x) or g(x) of TPE (Bergstra et al. 2011): a weighted
 * mixture of normal kernels truncated to the parameter's domain, one per observation plus a
 * prior kernel, in the parameter's internal coordinate ({@link Param}). This is Optuna 3.6.1's
 * univariate {@code _ParzenEstimator} (multivariate=False):
 * <ul>
 *   <li>kernel means: the observations, then the prior at the domain's middle;</li>
 *   <li>bandwidths: each kernel's larger gap to its sorted neighbours (the domain's ends, widened
 *       by half a grid step, are neighbours too); without {@code considerEndpoints} the first and
 *       last kernels take their inner gap only;</li>
 *   <li>the magic clip: bandwidths in [range / min(100, 1 + n + prior), range], range =
 *       high - low + step;</li>
 *   <li>the prior kernel: bandwidth = range, weight = {@code priorWeight}; weights then sum
 *       to 1.</li>
 * </ul>
 * Equal means are ordered by observation order with the prior last (Optuna leaves this to
 * numpy's unstable argsort, which differs between CPUs).
 */
final class ParzenEstimator {

    private static final double EPS = 1e-12;

    private final double[] weights;
    private final double[] mus;
    private final double[] sigmas;
    private final double low;
    private final double high;
    private final double step;
    /** Per kernel, log of the mass it keeps in the domain and log σ (the log-density's normaliser). */
    private final double[] logMass;
    private final double[] logSigma;

    private ParzenEstimator(double[] weights, double[] mus, double[] sigmas, Param param) {
        this.weights = weights;
        this.mus = mus;
        this.sigmas = sigmas;
        this.low = param.internalLow();
        this.high = param.internalHigh();
        this.step = param.step();
        this.logMass = new double[mus.length];
        this.logSigma = new double[mus.length];
        for (int k = 0; k < mus.length; k++) {
            logMass[k] = TruncatedNormal.logMass(a(k), b(k));
            logSigma[k] = Math.log(sigmas[k]);
        }
    }

    /**
     * Fits the estimator to observations (internal coordinates, in trial order) with their
     * unnormalised weights.
     */
    static ParzenEstimator fit(double[] observations, double[] observationWeights, Param param, TpeSettings settings) {
        return fit(observations, observationWeights, param, settings, 0);
    }

    /**
     * As {@link #fit(double[], double[], Param, TpeSettings)}; with {@code dimensions} > 0 this is
     * one dimension of multivariate TPE over that many parameters (Optuna's multivariate=True):
     * every observation's kernel has the same bandwidth 0.2 n^(−1/(dimensions + 4)) · range
     * (Scott's rule), then the magic clip.
     */
    static ParzenEstimator fit(double[] observations, double[] observationWeights, Param param, TpeSettings settings, int dimensions) {
        int n = observations.length;
        if (observationWeights.length != n) {
            throw new IllegalArgumentException(n + " observations but " + observationWeights.length + " weights");
        }
        double lo = param.internalLow(), hi = param.internalHigh(), step = param.step();
        boolean prior = settings.considerPrior() || n == 0;
        double priorMu = 0.5 * (lo + hi), range = hi - lo + step;

        // weights: the observations', then the prior's; normalised
        double[] weights = n == 0 ? new double[] {1.0} : Arrays.copyOf(observationWeights, prior ? n + 1 : n);
        if (n > 0 && prior) {
            weights[n] = settings.priorWeight();
        }
        double sum = 0;
        for (double w : weights) {
            sum += w;
        }
        for (int k = 0; k < weights.length; k++) {
            weights[k] /= sum;
        }

        // bandwidths from the gaps between sorted means, the prior's mean among them
        double[] mus = Arrays.copyOf(observations, prior ? n + 1 : n);
        if (prior) {
            mus[n] = priorMu;
        }
        Integer[] order = IntStream.range(0, mus.length).boxed().sorted(Comparator.comparingDouble(k -> mus[k])).toArray(Integer[]::new);
        double[] ends = new double[mus.length + 2]; // sorted means between the widened domain ends
        ends[0] = lo - step / 2;
        for (int i = 0; i < mus.length; i++) {
            ends[i + 1] = mus[order[i]];
        }
        ends[ends.length - 1] = hi + step / 2;
        double[] sorted = new double[mus.length];
        for (int i = 0; i < sorted.length; i++) {
            sorted[i] = Math.max(ends[i + 1] - ends[i], ends[i + 2] - ends[i + 1]);
        }
        if (!settings.considerEndpoints() && ends.length >= 4) {
            sorted[0] = ends[2] - ends[1];
            sorted[sorted.length - 1] = ends[ends.length - 2] - ends[ends.length - 3];
        }
        if (dimensions > 0) {
            Arrays.fill(sorted, 0.2 * Math.pow(Math.max(n, 1), -1.0 / (dimensions + 4)) * range);
        }
        double maxSigma = 1.0 * range;
        double minSigma = settings.considerMagicClip() ? 1.0 * range / Math.min(100.0, 1.0 + n + (prior ? 1 : 0)) : EPS;
        double[] sigmas = new double[mus.length];
        for (int i = 0; i < sorted.length; i++) {
            sigmas[order[i]] = Math.min(Math.max(sorted[i], minSigma), maxSigma);
        }
        if (prior) {
            sigmas[n] = range;
        }
        return new ParzenEstimator(weights, mus, sigmas, param);
    }

    double[] weights() {
        return weights.clone();
    }

    double[] mus() {
        return mus.clone();
    }

    double[] sigmas() {
        return sigmas.clone();
    }

    /** Kernel k's domain in its standard units (the grid cells' outer edges for discrete kernels). */
    private double a(int k) {
        return (low - step / 2 - mus[k]) / sigmas[k];
    }

    private double b(int k) {
        return (high + step / 2 - mus[k]) / sigmas[k];
    }

    /** A draw (internal coordinate): a kernel by weight, then its truncated normal, on the grid if discrete. */
    double sample(SplittableRandom rng) {
        return sampleKernel(kernel(rng), rng);
    }

    /** A kernel drawn by weight. */
    int kernel(SplittableRandom rng) {
        double u = rng.nextDouble(), cumulative = 0;
        int k = 0;
        while (k < weights.length - 1 && (cumulative += weights[k]) <= u) {
            k++;
        }
        return k;
    }

    /** A draw from kernel k's truncated normal (internal coordinate), on the grid if discrete. */
    double sampleKernel(int k, SplittableRandom rng) {
        double x = mus[k] + sigmas[k] * TruncatedNormal.sample(a(k), b(k), rng);
        if (step > 0) {
            x = Math.min(Math.max(low + Math.rint((x - low) / step) * step, low), high);
        }
        return x;
    }

    /**
     * log of the mixture's density at x (internal coordinate); for discrete kernels, log of the
     * mass of x's grid cell. Summed in log space around the largest term.
     */
    double logPdf(double x) {
        double[] terms = new double[mus.length];
        double max = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < mus.length; k++) {
            terms[k] = kernelLogPdf(k, x) + Math.log(weights[k]);
            max = Math.max(max, terms[k]);
        }
        if (max == Double.NEGATIVE_INFINITY) {
            max = 0;
        }
        double sum = 0;
        for (double t : terms) {
            sum += Math.exp(t - max);
        }
        return Math.log(sum) + max;
    }

    int kernelCount() {
        return mus.length;
    }

    /** Kernel k's log density at x (internal coordinate; log mass of x's cell if discrete). */
    double kernelLogPdf(int k, double x) {
        if (step == 0) {
            return TruncatedNormal.logPdf(x, a(k), b(k), mus[k], sigmas[k], logMass[k], logSigma[k]);
        }
        double cellLow = Math.max(x - step / 2, low - step / 2), cellHigh = Math.min(x + step / 2, high + step / 2);
        return TruncatedNormal.logMass((cellLow - mus[k]) / sigmas[k], (cellHigh - mus[k]) / sigmas[k]) - logMass[k];
    }
}
