package handsim.cards.tpe;

import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;

/**
 * The Tree-structured Parzen Estimator (Bergstra et al. 2011) and, for several objectives,
 * MOTPE (Ozaki et al. 2020), with the semantics of Optuna 3.6.1's {@code TPESampler}, for float
 * and integer parameters, in its default independent mode (multivariate=False) or, with
 * {@link TpeSettings#multivariate()}, its multivariate one ({@link JointEstimator}).
 *
 * <p>A suggestion, given the finished trials:
 * <ol>
 *   <li>fewer than {@code nStartupTrials}: every parameter uniformly at random;</li>
 *   <li>otherwise the trials are split: γ(n) = min(⌈0.1 n⌉, 25) good ones ("below"), the rest
 *       "above" ({@link TrialSplit});</li>
 *   <li>per parameter, independently: l(x) is fitted to the good trials' values, g(x) to the
 *       rest ({@link ParzenEstimator}); above trials weigh {@link #defaultWeights(int)}, below
 *       ones too for one objective, by hypervolume contribution for several;</li>
 *   <li>{@code nEiCandidates} candidates are drawn from l(x); the one of largest
 *       log l(x) - log g(x) (first on ties) is the suggestion; this maximises expected
 *       improvement (Bergstra et al. 2011, eq. 5).</li>
 * </ol>
 * The random draws use the caller's generator, so a suggestion is a function of the history and
 * that generator's seed only. They do not reproduce Optuna's numbers (numpy's generator); every
 * deterministic step does.
 */
public final class TpeSampler {

    private final List<Param> space;
    private final List<Direction> directions;
    private final TpeSettings settings;

    public TpeSampler(List<Param> space, List<Direction> directions, TpeSettings settings) {
        if (space.isEmpty()) {
            throw new IllegalArgumentException("the search space has no parameters");
        }
        if (directions.isEmpty()) {
            throw new IllegalArgumentException("a study needs at least one objective direction");
        }
        this.space = List.copyOf(space);
        this.directions = List.copyOf(directions);
        this.settings = settings;
    }

    public List<Param> space() {
        return space;
    }

    public List<Direction> directions() {
        return directions;
    }

    public TpeSettings settings() {
        return settings;
    }

    /** Parameter values (search-space order, own units) for the next trial, from the finished trials. */
    public double[] suggest(List<CompletedTrial> history, SplittableRandom rng) {
        for (CompletedTrial t : history) {
            if (t.params().length != space.size() || t.values().length != directions.size()) {
                throw new IllegalArgumentException("trial " + t.number() + ": " + t.params().length + " params and " + t.values().length
                        + " values, the sampler has " + space.size() + " params and " + directions.size() + " objectives");
            }
        }
        double[] out = new double[space.size()];
        if (history.size() < settings.nStartupTrials()) {
            for (int i = 0; i < out.length; i++) {
                out[i] = space.get(i).random(rng);
            }
            return out;
        }
        Estimators model = fit(history);
        if (settings.multivariate()) {
            return model.bestJoint(rng);
        }
        for (int i = 0; i < out.length; i++) {
            double[] candidates = new double[settings.nEiCandidates()];
            for (int c = 0; c < candidates.length; c++) {
                candidates[c] = space.get(i).fromInternal(model.below[i].sample(rng));
            }
            out[i] = model.best(i, candidates);
        }
        return out;
    }

    /** γ(n): how many of n finished trials count as good, Optuna's {@code default_gamma}. */
    static int gamma(int n) {
        return Math.min((int) Math.ceil(0.1 * n), 25);
    }

    /**
     * Weights of n trials in trial order, Optuna's {@code default_weights}: all 1 below 25; from
     * 25 on, the oldest n - 25 ramp linearly from 1/n up to 1 and the newest 25 weigh 1
     * (Bergstra et al. 2013).
     */
    static double[] defaultWeights(int n) {
        double[] w = new double[n];
        Arrays.fill(w, 1.0);
        int ramp = n - 25;
        if (ramp > 0) {
            double start = 1.0 / n, step = (1.0 - start) / (ramp - 1);
            for (int i = 0; i < ramp; i++) {
                w[i] = ramp == 1 ? start : i == ramp - 1 ? 1.0 : i * step + start; // numpy.linspace(1/n, 1, n - 25)
            }
        }
        return w;
    }

    /** l(x) and g(x) of every parameter for one history. */
    Estimators fit(List<CompletedTrial> history) {
        TrialSplit.Split split = TrialSplit.split(history, directions, gamma(history.size()));
        double[] belowWeights = directions.size() > 1 ? TrialSplit.hypervolumeWeights(split.below(), directions) : defaultWeights(split.below().size());
        double[] aboveWeights = defaultWeights(split.above().size());
        ParzenEstimator[] below = new ParzenEstimator[space.size()], above = new ParzenEstimator[space.size()];
        int dimensions = settings.multivariate() ? space.size() : 0;
        for (int i = 0; i < space.size(); i++) {
            below[i] = ParzenEstimator.fit(internal(split.below(), i), belowWeights, space.get(i), settings, dimensions);
            above[i] = ParzenEstimator.fit(internal(split.above(), i), aboveWeights, space.get(i), settings, dimensions);
        }
        return new Estimators(split, below, above);
    }

    private double[] internal(List<CompletedTrial> trials, int param) {
        double[] x = new double[trials.size()];
        for (int k = 0; k < x.length; k++) {
            x[k] = space.get(param).toInternal(trials.get(k).param(param));
        }
        return x;
    }

    /** The split and each parameter's l(x) (below) and g(x) (above). */
    final class Estimators {
        final TrialSplit.Split split;
        final ParzenEstimator[] below;
        final ParzenEstimator[] above;

        Estimators(TrialSplit.Split split, ParzenEstimator[] below, ParzenEstimator[] above) {
            this.split = split;
            this.below = below;
            this.above = above;
        }

        /** log l(x) - log g(x) of parameter i at a value in its own units. */
        double acquisition(int i, double value) {
            double x = space.get(i).toInternal(value);
            return below[i].logPdf(x) - above[i].logPdf(x);
        }

        /**
         * Multivariate TPE's suggestion: {@code nEiCandidates} whole points drawn from the joint
         * l(x), the one of largest joint log l(x) − log g(x) (the first of equals), in the
         * parameters' own units.
         */
        double[] bestJoint(SplittableRandom rng) {
            JointEstimator l = new JointEstimator(below);
            double[][] candidates = new double[settings.nEiCandidates()][];
            for (int c = 0; c < candidates.length; c++) {
                double[] drawn = l.sample(rng);
                candidates[c] = new double[drawn.length];
                for (int i = 0; i < drawn.length; i++) {
                    candidates[c][i] = space.get(i).fromInternal(drawn[i]);
                }
            }
            return chooseJoint(candidates);
        }

        /** The candidate (own units) of largest joint log l(x) − log g(x), evaluated after rounding to the grid as Optuna does; the first of equals. */
        double[] chooseJoint(double[][] candidates) {
            double[] best = null;
            double bestValue = Double.NEGATIVE_INFINITY;
            for (double[] values : candidates) {
                double a = jointAcquisition(values);
                if (a > bestValue || best == null) {
                    best = values;
                    bestValue = a;
                }
            }
            return best.clone();
        }

        /** Joint log l(x) − log g(x) at a point in the parameters' own units. */
        double jointAcquisition(double[] values) {
            return jointLogPdf(true, values) - jointLogPdf(false, values);
        }

        /** Joint log l(x) (below) or log g(x) at a point in the parameters' own units. */
        double jointLogPdf(boolean ofBelow, double[] values) {
            double[] x = new double[values.length];
            for (int i = 0; i < x.length; i++) {
                x[i] = space.get(i).toInternal(values[i]);
            }
            return new JointEstimator(ofBelow ? below : above).logPdf(x);
        }

        /** The candidate of largest acquisition, the first of equals. */
        double best(int i, double[] candidates) {
            int best = 0;
            double bestValue = Double.NEGATIVE_INFINITY;
            for (int c = 0; c < candidates.length; c++) {
                double a = acquisition(i, candidates[c]);
                if (a > bestValue || c == 0) {
                    best = c;
                    bestValue = a;
                }
            }
            return candidates[best];
        }
    }
}
