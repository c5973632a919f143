package handsim.cards.tpe;

/**
 * The TPE sampler's settings, named as Optuna 3.6.1's {@code TPESampler} arguments. The
 * γ(n) = min(⌈0.1 n⌉, 25) split and the default weights are Optuna's and fixed.
 *
 * @param nStartupTrials    trials sampled at random before TPE starts (counted over finished trials)
 * @param nEiCandidates     candidates drawn from l(x) per parameter; the one with the largest
 *                          log l(x) - log g(x) is suggested
 * @param considerPrior     whether each estimator has a prior kernel (the domain's middle, width = range)
 * @param priorWeight       the prior kernel's weight (> 0)
 * @param considerMagicClip whether bandwidths have a lower bound of range / min(100, 1 + n + prior)
 * @param considerEndpoints whether the first and last kernels' bandwidths also see the domain's ends
 * @param multivariate      multivariate TPE: one joint estimator over all parameters, kernels of
 *                          Scott's bandwidth, candidates drawn and compared as whole points
 *                          (Optuna's {@code multivariate=True}); else one estimator per parameter
 */
public record TpeSettings(int nStartupTrials, int nEiCandidates, boolean considerPrior, double priorWeight,
        boolean considerMagicClip, boolean considerEndpoints, boolean multivariate) {

    /** Optuna 3.6.1's defaults: 10 start-up trials, 24 candidates, prior of weight 1, magic clip, no endpoints, independent. */
    public static final TpeSettings OPTUNA_DEFAULTS = new TpeSettings(10, 24, true, 1.0, true, false, false);

    /** Independent (multivariate=False) settings. */
    public TpeSettings(int nStartupTrials, int nEiCandidates, boolean considerPrior, double priorWeight,
            boolean considerMagicClip, boolean considerEndpoints) {
        this(nStartupTrials, nEiCandidates, considerPrior, priorWeight, considerMagicClip, considerEndpoints, false);
    }

    public TpeSettings {
        if (nStartupTrials < 0) {
            throw new IllegalArgumentException("nStartupTrials: must be >= 0, got " + nStartupTrials);
        }
        if (nEiCandidates < 1) {
            throw new IllegalArgumentException("nEiCandidates: must be >= 1, got " + nEiCandidates);
        }
        if (!(priorWeight > 0) || !Double.isFinite(priorWeight)) {
            throw new IllegalArgumentException("priorWeight: must be a finite number > 0, got " + priorWeight);
        }
    }
}
