package handsim.learn;

import handsim.rollout.LocalRollouts;
import handsim.rollout.Rollouts;
import java.util.List;
import java.util.function.ToDoubleFunction;
import org.apache.commons.math3.exception.TooManyEvaluationsException;
import org.apache.commons.math3.optim.InitialGuess;
import org.apache.commons.math3.optim.MaxEval;
import org.apache.commons.math3.optim.SimpleBounds;
import org.apache.commons.math3.optim.nonlinear.scalar.GoalType;
import org.apache.commons.math3.optim.nonlinear.scalar.ObjectiveFunction;
import org.apache.commons.math3.optim.nonlinear.scalar.noderiv.CMAESOptimizer;
import org.apache.commons.math3.random.MersenneTwister;

/**
 * CMA-ES (Hansen 2006) for the imitation examples of paper sec. 4.4: a thin wrapper over
 * commons-math3's {@link CMAESOptimizer} that always returns the best point it evaluated
 * (also when the evaluation budget runs out). commons-math evaluates a generation's candidates
 * one after the other; parallelism comes from solving independent problems (one per initial
 * condition) at once with {@link #minimizeAll}.
 */
public final class Cmaes {

    /**
     * One minimisation.
     *
     * @param objective the function to minimise; called from one thread per problem
     * @param x0 start point
     * @param sigma initial step size per coordinate
     * @param lower lower bounds, or null for none (then upper is null too)
     * @param upper upper bounds, or null
     * @param population offspring per generation, 0 for the default 4 + floor(3 ln n)
     * @param maxEvaluations objective evaluations at most
     * @param seed seeds the sampling (same seed, same result)
     */
    public record Problem(ToDoubleFunction<double[]> objective, double[] x0, double[] sigma, double[] lower,
            double[] upper, int population, int maxEvaluations, long seed) {
    }

    /** The best point evaluated, its value and the number of evaluations made. */
    public record Result(double[] point, double value, int evaluations) {
    }

    private Cmaes() {
    }

    public static Result minimize(Problem p) {
        int n = p.x0().length;
        if (p.sigma().length != n || (p.lower() == null) != (p.upper() == null)
                || p.lower() != null && (p.lower().length != n || p.upper().length != n)) {
            throw new IllegalArgumentException("x0, sigma and bounds must all have " + n + " entries");
        }
        int lambda = p.population() > 0 ? p.population() : 4 + (int) Math.floor(3 * Math.log(n));
        double[] best = {Double.POSITIVE_INFINITY};
        double[][] bestPoint = {p.x0().clone()};
        int[] evaluations = {0};
        ObjectiveFunction tracked = new ObjectiveFunction(x -> {
            double v = p.objective().applyAsDouble(x);
            evaluations[0]++;
            if (v < best[0]) {
                best[0] = v;
                bestPoint[0] = x.clone();
            }
            return v;
        });
        CMAESOptimizer optimizer = new CMAESOptimizer(Integer.MAX_VALUE, 0, true, 0, 0, new MersenneTwister(p.seed()),
                false, null);
        try {
            optimizer.optimize(new MaxEval(p.maxEvaluations()), tracked, GoalType.MINIMIZE, new InitialGuess(p.x0()),
                    p.lower() == null ? SimpleBounds.unbounded(n) : new SimpleBounds(p.lower(), p.upper()),
                    new CMAESOptimizer.Sigma(p.sigma()), new CMAESOptimizer.PopulationSize(lambda));
        } catch (TooManyEvaluationsException budgetSpent) {
            // the best point so far is the answer
        }
        return new Result(bestPoint[0], best[0], evaluations[0]);
    }

    public static Result minimize(ToDoubleFunction<double[]> objective, double[] x0, double[] sigma, double[] lower,
            double[] upper, int population, int maxEvaluations, long seed) {
        return minimize(new Problem(objective, x0, sigma, lower, upper, population, maxEvaluations, seed));
    }

    /**
     * Solves independent problems on {@code workers} threads; results in input order and, each
     * problem being seeded, the same for any number of workers.
     */
    public static List<Result> minimizeAll(List<Problem> problems, int workers) {
        try (Rollouts<Object> pool = new LocalRollouts<>(workers, Object::new)) {
            return pool.run(problems.size(), worker -> i -> minimize(problems.get(i)));
        }
    }
}
