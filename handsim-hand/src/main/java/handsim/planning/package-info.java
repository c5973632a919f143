/**
 * Throws chosen by trying them first in a twin world that knows the future exactly: the {@link
 * handsim.planning.ThrowPlanner} (the policy proposes, variations are tried, the hand makes the
 * best; {@code evaluate --plan}), the {@link handsim.planning.ThrowTeacher} that labels a
 * learner's decisions with the nearest throw that works (DAgger), and the {@link
 * handsim.planning.TwinEpisode} both play their tries in. Settings in {@code configs/planner.json}
 * ({@link handsim.planning.PlannerConfig}). Figures that use it are planner-assisted: the planner
 * is an oracle, never the paper's learned method.
 *
 * <p>Imports {@code handsim.task} (episodes and their checkpoints) and what it stands on ({@code
 * handsim.math}, {@code handsim.config}, {@code handsim.sim}, {@code handsim.control}); never an
 * engine (the twin simulator is handed in), the evaluation or the app.
 */
package handsim.planning;
