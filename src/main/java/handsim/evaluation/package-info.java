/**
 * Evaluating a controller on a task: seeded catch-and-throw episodes ({@link
 * handsim.evaluation.CatchEvaluation}), the throw planner that tries each throw in a twin world
 * first ({@link handsim.evaluation.ThrowPlanner}) and the teacher that labels a learner's
 * decisions in the same twin ({@link handsim.evaluation.ThrowTeacher}; both play their tries in a
 * {@link handsim.evaluation.TwinEpisode}), and one evaluation per kind of run of {@code
 * handsim evaluate}: {@link handsim.evaluation.HeightEvaluation} (the height errors, Fig. 5),
 * {@link handsim.evaluation.BoxEvaluation} (the box trials and their success map, Fig. 8),
 * {@link handsim.evaluation.FlipEvaluation} (flip-and-catch loops in a row, sec. 4.4) and {@link
 * handsim.evaluation.SensitivityEvaluation} (how a nudged launch spreads through the loops);
 * each writes its summary (JSON, CSV, console, PNG) and journals finished episodes so that a
 * killed run resumes ({@link handsim.evaluation.EpisodeJournal}).
 *
 * <p>Imports {@code handsim.task} and what it stands on ({@code handsim.math}, {@code
 * handsim.config}, {@code handsim.model}, {@code handsim.kin}, {@code handsim.sim}, {@code
 * handsim.control}), {@code handsim.rollout} (parallel episodes), {@code handsim.report} (charts,
 * atomic files) and Jackson; never an engine (a twin simulator is handed in), picocli or the app.
 */
package handsim.evaluation;
