package handsim.learn;

import java.util.ArrayList;
import java.util.List;

/**
 * One {@link Cmaes} minimisation a generation at a time: {@link #next} gives the points to
 * evaluate next (the start point, then each generation's candidates), {@link #tell} takes their
 * values, and once no points are left {@link #result} is {@link Cmaes#minimize}'s result for an
 * objective with those values, bit for bit. So the candidates of a generation, of many
 * minimisations at once, can be evaluated anywhere (a cluster's executors) in any order.
 *
 * <p>commons-math's optimizer asks for one value at a time, but draws a generation's λ
 * candidates before it uses any of their values. {@link #next} replays the optimizer from its
 * seed with the values told so far, answers the first λ unknown points of the generation with a
 * placeholder while noting them, and stops it at the next generation's first point: those noted
 * are the generation. A replay is cheap beside one evaluation (a simulated throw).
 */
public final class CmaesGenerations {

    private final Cmaes.Problem problem;
    private final int lambda;
    private final List<Double> values = new ArrayList<>();
    private List<double[]> pending = List.of();
    private Cmaes.Result result;

    /** A minimisation of {@code problem}'s settings (its objective is not called: the values come by {@link #tell}). */
    public CmaesGenerations(Cmaes.Problem problem) {
        this.problem = problem;
        int n = problem.x0().length;
        this.lambda = problem.population() > 0 ? problem.population() : 4 + (int) Math.floor(3 * Math.log(n));
    }

    /** Thrown by the replay's objective at the first point past the generation being collected. */
    private static final class GenerationCollected extends RuntimeException {
        private static final long serialVersionUID = 1L;

        GenerationCollected() {
            super(null, null, false, false);
        }
    }

    /** The points whose values come next (empty once the minimisation is over). */
    public List<double[]> next() {
        if (result != null) {
            return List.of();
        }
        if (!pending.isEmpty()) {
            return pending;
        }
        int known = values.size();
        // evaluation 0 is the start point, then generation g holds evaluations 1 + (g-1)λ .. gλ
        int end = known == 0 ? 1 : known + lambda;
        List<double[]> noted = new ArrayList<>();
        int[] asked = {0};
        Cmaes.Problem replay = new Cmaes.Problem(x -> {
            int k = asked[0]++;
            if (k < known) {
                return values.get(k);
            }
            if (k >= end) {
                throw new GenerationCollected();
            }
            noted.add(x.clone());
            return 0; // a placeholder: the optimizer uses a generation's values only once it has drawn all its points
        }, problem.x0(), problem.sigma(), problem.lower(), problem.upper(), problem.population(), problem.maxEvaluations(), problem.seed());
        try {
            Cmaes.Result r = Cmaes.minimize(replay);
            if (noted.isEmpty()) {
                result = r; // the optimizer stopped (converged, or its budget spent) on the values told
                return List.of();
            }
        } catch (GenerationCollected collected) {
            // the generation is complete
        }
        pending = List.copyOf(noted);
        return pending;
    }

    /** The values of the points {@link #next} gave, in its order. */
    public void tell(double[] valuesOfNext) {
        if (valuesOfNext.length != pending.size()) {
            throw new IllegalArgumentException(pending.size() + " values expected, got " + valuesOfNext.length);
        }
        for (double v : valuesOfNext) {
            values.add(v);
        }
        pending = List.of();
    }

    /** Whether the minimisation is over ({@link #next} gave no points). */
    public boolean done() {
        return result != null;
    }

    /** The best point evaluated, its value and the evaluations made: {@link Cmaes#minimize}'s result. */
    public Cmaes.Result result() {
        if (result == null) {
            throw new IllegalStateException("the minimisation is not over: call next() until it gives no points");
        }
        return result;
    }
}
