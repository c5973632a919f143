package handsim.rollout;

import handsim.sim.Simulator;

/**
 * What to run: {@link #prepare} is called once per worker and run with the worker's own
 * simulator, and builds the worker's private state (controllers, goal sequences, buffers);
 * the {@link Rollout} it returns then runs rollouts by index on that worker.
 *
 * @param <R> the result of one rollout
 */
@FunctionalInterface
public interface RolloutTask<R> {

    Rollout<R> prepare(Simulator sim);

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
