/**
 * Evaluating a controller on a task: seeded catch-and-throw episodes ({@link
 * handsim.evaluation.CatchEvaluation}), with every throw chosen by the twin-world planner when
 * asked ({@link handsim.planning.ThrowPlanner}), and one evaluation per kind of run of {@code
 * handsim evaluate}: {@link handsim.evaluation.HeightEvaluation} (the height errors, Fig. 5),
 * {@link handsim.evaluation.BoxEvaluation} (the box trials and their success map, Fig. 8),
 * {@link handsim.evaluation.FlipEvaluation} (flip-and-catch loops in a row, sec. 4.4) and {@link
 * handsim.evaluation.SensitivityEvaluation} (how a nudged launch spreads through the loops);
 * each writes its summary (JSON, CSV, console, PNG) and journals finished episodes so that a
 * killed run resumes ({@link handsim.evaluation.EpisodeJournal}).
 *
 * <p>Imports {@code handsim.task} and what it stands on ({@code handsim.math}, {@code
 * handsim.config}, {@code handsim.model}, {@code handsim.kin}, {@code handsim.sim}, {@code
 * handsim.control}), {@code handsim.planning} (the twin-world planner), {@code handsim.rollout} (parallel episodes), {@code handsim.report} (charts,
 * atomic files) and Jackson; never an engine (a twin simulator is handed in), picocli or the app.
 */
package handsim.evaluation;
