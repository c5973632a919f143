package handsim.cards.tpe;

import java.util.SplittableRandom;

/**
 * l(x) or g(x) of multivariate TPE (Optuna 3.6.1's {@code multivariate=True}; Falkner et al.
 * 2018): a weighted mixture of product kernels, kernel k being the product over the parameters
 * of each one's truncated normal k ({@link ParzenEstimator} fitted with the multivariate
 * bandwidth), all sharing the mixture weights. A draw picks one kernel for every parameter, so
 * the parameters' dependence among the good trials is kept.
 */
final class JointEstimator {

    private final ParzenEstimator[] dims;
    private final double[] logWeights;

    JointEstimator(ParzenEstimator[] dims) {
        this.dims = dims.clone();
        double[] w = dims[0].weights();
        logWeights = new double[w.length];
        for (int k = 0; k < w.length; k++) {
            logWeights[k] = Math.log(w[k]);
        }
    }

    ParzenEstimator dimension(int i) {
        return dims[i];
    }

    /** A draw (internal coordinates): one kernel by weight, then each parameter from it. */
    double[] sample(SplittableRandom rng) {
        int k = dims[0].kernel(rng);
        double[] x = new double[dims.length];
        for (int i = 0; i < dims.length; i++) {
            x[i] = dims[i].sampleKernel(k, rng);
        }
        return x;
    }

    /** log of the mixture's density at x (internal coordinates), summed in log space around the largest term. */
    double logPdf(double[] x) {
        int kernels = logWeights.length;
        double[] terms = new double[kernels];
        double max = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < kernels; k++) {
            double t = logWeights[k];
            for (int i = 0; i < dims.length; i++) {
                t += dims[i].kernelLogPdf(k, x[i]);
            }
            terms[k] = t;
            max = Math.max(max, t);
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
}
