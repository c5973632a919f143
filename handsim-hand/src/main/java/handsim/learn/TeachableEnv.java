package handsim.learn;

/**
 * An environment whose decisions a teacher can label (the expert of DAgger, Ross et al. 2011):
 * between {@link #reset} or {@link #step} and the next step, the environment waits at a decision,
 * and {@link #label} asks the teacher what to do there, given the learner's own proposal, without
 * changing the episode.
 */
public interface TeachableEnv extends Env {

    /**
     * As {@link Env#reset}, or null when the episode of {@code seed} ends before any decision the
     * learner makes (an environment that leads in to the learner's decisions by other means).
     */
    @Override
    double[] reset(long seed);

    /**
     * The teacher's label for the decision the environment waits at; {@code seed} seeds the
     * teacher's search, so that the same state, proposal and seed give the same label.
     */
    Demonstration label(double[] proposal, long seed);
}
