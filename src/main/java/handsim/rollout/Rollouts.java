package handsim.rollout;

import java.util.List;

/**
 * Runs independent rollouts, possibly in parallel. Evaluation and training use this interface
 * and never see threads or engines; {@link LocalRollouts} is the embedded implementation.
 */
public interface Rollouts extends AutoCloseable {

    /** Called on the caller's thread with each result, in index order, as soon as it and all before it are done. */
    @FunctionalInterface
    interface Listener<R> {
        void onResult(int index, R result);
    }

    /** Number of rollouts that may run at once. */
    int workers();

    /**
     * Runs rollouts {@code 0 .. count-1} of {@code task} and returns their results in index
     * order. A rollout that throws stops the run and the exception is rethrown here.
     */
    <R> List<R> run(int count, RolloutTask<R> task, Listener<? super R> listener);

    default <R> List<R> run(int count, RolloutTask<R> task) {
        return run(count, task, (i, r) -> { });
    }

    /** Stops the workers and closes their simulators. */
    @Override
    void close();
}
