package handsim.learn;

/**
 * A task with one decision per step, as the learner sees it. In handsim a step is one THROW:
 * the action is the throw's parameters and the step lasts until the next throw is due (or the
 * object is lost), about 0.4 s of simulation.
 *
 * <p>Contract: {@link #reset(long)} fully determines the episode together with the actions, so
 * that several instances are interchangeable and a run is reproducible from its seeds. An
 * instance is used by one thread at a time.
 */
public interface Env {

    /** Length of the observation vector. */
    int observationSize();

    /** Length of the action vector; actions are in [-1, 1]^k (the actor's tanh range). */
    int actionSize();

    /** Starts a new episode and returns its first observation. */
    double[] reset(long seed);

    /** Applies one decision. The action has {@link #actionSize()} entries in [-1, 1]. */
    Step step(double[] action);

    /**
     * The outcome of one decision.
     *
     * @param observation the next observation (also given at an episode end: after a
     *     truncation the learner bootstraps from it)
     * @param reward the reward of this decision
     * @param terminal a real end (e.g. the object was dropped): no value follows, no bootstrap
     * @param truncated a cut-off (time or loop limit): the episode stops here but the state
     *     still had a future, so the learner bootstraps from {@code observation}
     */
    record Step(double[] observation, double reward, boolean terminal, boolean truncated) {

        /** Whether the episode is over, for either reason. */
        public boolean done() {
            return terminal || truncated;
        }
    }
}
