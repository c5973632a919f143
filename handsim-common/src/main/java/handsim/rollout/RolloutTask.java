package handsim.rollout;


/**
 * What to run: {@link #prepare} is called once per worker with what the worker owns (its own
 * simulator, its own environment), and builds the worker's private state (controllers, goal
 * sequences, buffers); the {@link Rollout} it returns then runs rollouts by index on that worker.
 *
 * @param <W> what each worker owns
 * @param <R> the result of one rollout
 */
@FunctionalInterface
public interface RolloutTask<W, R> {

    Rollout<R> prepare(W worker);

    /** One worker's runner of rollouts. */
    @FunctionalInterface
    interface Rollout<R> {

        /**
         * Runs rollout {@code index}. Its result must depend on {@code index} alone (seed the
         * run from it, reset the simulator), not on what this worker ran before.
         */
        R run(int index);
    }
}
