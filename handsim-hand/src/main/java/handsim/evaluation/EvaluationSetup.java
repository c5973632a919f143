package handsim.evaluation;

import handsim.control.ControllerConfig;
import handsim.control.ThrowPolicy;
import handsim.planning.PlannerConfig;
import handsim.sim.ObjectSpec;
import handsim.sim.Simulator;
import handsim.task.EpisodeLimits;
import handsim.task.LaunchDistribution;
import handsim.task.ThrowTask;
import java.io.PrintStream;
import java.util.function.Function;
import java.util.function.UnaryOperator;

/**
 * What an evaluation runs with, wired by the command.
 *
 * @param controller the controller's settings (configs/controller.json)
 * @param object the object thrown, before a seed varies it
 * @param policies a worker's throw policy for its own task (the task's nominal throw, or a learned policy)
 * @param planning the planner's settings, or null without one
 * @param twins a twin of a worker's simulator for the planner: the same model and config on an engine of its own
 * @param watcher told after every tick (an animation export), or null
 * @param journal the finished episodes of this run and of an earlier, killed one (with --json), or null
 * @param console where the progress and summary lines go
 */
public record EvaluationSetup(ControllerConfig controller, ObjectSpec object, EpisodeLimits limits,
        LaunchDistribution launches, EvaluationConfig config, Function<ThrowTask, ThrowPolicy> policies,
        PlannerConfig planning, UnaryOperator<Simulator> twins, CatchEvaluation.TickWatcher watcher, EpisodeJournal journal,
        PrintStream console) {
}
