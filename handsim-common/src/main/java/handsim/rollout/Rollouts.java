package handsim.rollout;

import java.util.List;

/**
 * Runs independent rollouts, possibly in parallel, each on a worker that owns a resource of its
 * own ({@code W}: a simulator, a learner's environment). Evaluation and training use this
 * interface and never see threads or engines; {@link LocalRollouts} is the embedded
 * implementation.
 *
 * @param <W> what each worker owns and hands to the rollouts it runs
 */
public interface Rollouts<W> extends AutoCloseable {

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
    <R> List<R> run(int count, RolloutTask<W, R> task, Listener<? super R> listener);

    default <R> List<R> run(int count, RolloutTask<W, R> task) {
        return run(count, task, (i, r) -> { });
    }

    /** Stops the workers and closes what they own (when it can be closed). */
    @Override
    void close();
}
