/**
 * The catch-and-throw episode and the tasks it serves: the one step order every run uses
 * ({@link handsim.task.ServoLoop}); {@link handsim.task.CatchThrowEpisode}, which advances to each
 * throw's decision and takes the decision as an argument, its whole state a world state and an
 * {@link handsim.task.EpisodeState}; the tasks (height, box, flip: goals, rewards eq. 5-7,
 * success, their rules from {@code configs/tasks/}); the launch distribution, the episode limits
 * and the learner's state vector.
 *
 * <p>Imports {@code handsim.math}, {@code handsim.config}, {@code handsim.model}, {@code
 * handsim.kin}, {@code handsim.sim} (the interface, never an engine) and {@code handsim.control};
 * nothing above it (no evaluation, scene, learning or app).
 */
package handsim.task;
