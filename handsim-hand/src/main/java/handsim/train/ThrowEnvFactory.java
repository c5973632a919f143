package handsim.train;

import handsim.control.ControllerConfig;
import handsim.control.ThrowSpace;
import handsim.sim.ObjectSpec;
import handsim.sim.Simulator;
import handsim.evaluation.CatchEvaluation;
import handsim.task.EpisodeLimits;
import handsim.task.LaunchDistribution;
import handsim.task.StateVector;
import handsim.task.ThrowTask;
import java.util.function.Supplier;

/**
 * Everything needed to make {@link ThrowEnv}s of one task and object; the app wires it (the
 * engine is its choice), training and evaluation make environments from it on their workers.
 *
 * @param tasks a fresh task per environment (tasks hold an episode's goals)
 */
public record ThrowEnvFactory(String task, ObjectSpec object, Supplier<ThrowTask> tasks, ControllerConfig controller,
        EpisodeLimits limits, LaunchDistribution launches, ThrowSpace space, ThrowEnv.Settings settings, StateVector state) {

    /** An environment on {@code sim} (which it owns from then on). */
    public ThrowEnv create(Simulator sim) {
        ThrowTask t = tasks.get();
        return new ThrowEnv(sim, t, space, state, settings, 
                new CatchEvaluation(controller, limits, launches, object, t, CatchEvaluation.DECIDED_BY_CALLER));
    }

    /** The length of the state the environments give. */
    public int observationSize() {
        return state.size(tasks.get().goalSize());
    }
}
