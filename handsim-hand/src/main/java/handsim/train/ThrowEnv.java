package handsim.train;

import handsim.control.Observation;
import handsim.control.ThrowDecision;
import handsim.control.ThrowParameters;
import handsim.control.ThrowSpace;
import handsim.learn.Env;
import handsim.sim.SimulationDiverged;
import handsim.sim.Simulator;
import handsim.evaluation.CatchEvaluation;
import handsim.task.CatchThrowEpisode;
import handsim.task.LoopRecord;
import handsim.task.StateVector;
import handsim.task.ThrowTask;
import java.util.List;

/**
 * A throw task as the learner sees it (on a simulator it uses but does not own): an episode starts with an object thrown into the hand
 * and caught; every step is one THROW, whose parameters are the action (mapped from [-1, 1]^7
 * onto the {@link ThrowSpace}), and lasts until the next THROW is due. The reward is the task's
 * (eq. 5-7) for the throw and its catch, plus the run's {@link SpinShaping} if any; a drop, a loop cut off by time or a diverged
 * simulation is a real end (terminal). The loop cap of an episode is the trainer's truncation.
 *
 * <p>{@link #reset} is a function of its seed alone (the simulator is reset, the launch and the
 * task's goals are drawn from the seed), so environments on several workers are
 * interchangeable. If the launched object is not caught, the next launch derived from the seed
 * is tried.
 */
public final class ThrowEnv implements Env {

    /**
     * @param firstCatchAttempts launches tried per reset before giving up
     * @param divergedReward the reward of a throw whose simulation diverged (an episode end)
     * @param spinShaping a training-only term added to the task's reward ({@link SpinShaping#NONE}: none)
     * @param endAtFailedThrow end the episode (terminal) at the first throw that is not a success
     *     of the task, as evaluation does, instead of only at a drop
     */
    public record Settings(int firstCatchAttempts, double divergedReward, SpinShaping spinShaping, boolean endAtFailedThrow) {
    }

    private final Simulator sim;
    private final ThrowTask task;
    private final ThrowSpace space;
    private final StateVector stateVector;
    private final Settings settings;
    private final CatchEvaluation evaluation;
    private CatchThrowEpisode episode;
    private double[] state;
    private int diverged;

    /**
     * @param evaluation starts the episodes of {@code task} (their throws are the actions, {@link
     *     CatchEvaluation#DECIDED_BY_CALLER})
     */
    public ThrowEnv(Simulator sim, ThrowTask task, ThrowSpace space, StateVector stateVector, Settings settings,
            CatchEvaluation evaluation) {
        this.sim = sim;
        this.task = task;
        this.space = space;
        this.stateVector = stateVector;
        this.settings = settings;
        this.evaluation = evaluation;
    }

    @Override
    public int observationSize() {
        return stateVector.size(task.goalSize());
    }

    @Override
    public int actionSize() {
        return ThrowParameters.SIZE;
    }

    /** Throws whose simulation diverged so far (counted, logged by the caller, never hidden). */
    public int divergedThrows() {
        return diverged;
    }

    @Override
    public double[] reset(long seed) {
        for (int attempt = 0; attempt < settings.firstCatchAttempts(); attempt++) {
            episode = evaluation.start(sim, seed * settings.firstCatchAttempts() + attempt);
            try {
                Observation first = episode.advanceToDecision();
                if (first != null) {
                    state = stateVector.encode(first, task.goal());
                    return state.clone();
                }
            } catch (SimulationDiverged e) {
                diverged++;
                System.err.println("handsim: simulation diverged while catching the launch of seed " + seed + " (" + e.getMessage()
                        + "); trying the next launch");
            }
        }
        throw new IllegalStateException("no launch of seed " + seed + " was caught in " + settings.firstCatchAttempts()
                + " attempts: the task cannot start");
    }

    @Override
    public Step step(double[] action) {
        return throwWith(space.fromAction(action));
    }

    /** {@link #step} with the throw's parameters themselves (not an action mapped onto the throw box). */
    public Step throwWith(ThrowParameters parameters) {
        if (episode == null || episode.status() != CatchThrowEpisode.Status.RUNNING) {
            throw new IllegalStateException("step() needs a running episode: call reset() first");
        }
        Observation next;
        try {
            episode.decide(ThrowDecision.of(parameters));
            next = episode.advanceToDecision();
        } catch (SimulationDiverged e) {
            diverged++;
            System.err.println("handsim: simulation diverged during a throw (" + e.getMessage() + "); the episode ends there");
            return new Step(state.clone(), settings.divergedReward(), true, false);
        }
        List<LoopRecord> loops = episode.loops();
        LoopRecord thrown = loops.get(loops.size() - 1);
        double reward = task.reward(thrown) + settings.spinShaping().bonus(thrown);
        if (next == null || settings.endAtFailedThrow() && !task.success(thrown)) {
            return new Step(stateVector.encode(episode.observe(), task.goal()), reward, true, false);
        }
        state = stateVector.encode(next, task.goal());
        return new Step(state.clone(), reward, false, false);
    }

    /** The task the episodes play (its goals are drawn at each reset). */
    public ThrowTask task() {
        return task;
    }

    /** The episode being played (for inspection). */
    public CatchThrowEpisode episode() {
        return episode;
    }
}
