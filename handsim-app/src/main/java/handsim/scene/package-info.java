/**
 * Scenes to watch and steer: an {@link handsim.scene.InteractiveScene} gives a snapshot, a status,
 * a goal and takes commands; the catch-and-throw loop ({@link handsim.scene.CatchLoopScene}), the
 * ball held in the palm ({@link handsim.scene.HeldBallScene}), offered by a {@link
 * handsim.scene.SceneCatalog} and switched by a {@link handsim.scene.SwitchingScene}; and the live
 * run that paces a scene against the wall clock for the viewer ({@link handsim.scene.LiveRun},
 * {@link handsim.scene.SimClock}).
 *
 * <p>Imports {@code handsim.task}, {@code handsim.evaluation} (seeded episodes), {@code handsim.planning}
 * (the planner's throws), {@code handsim.taskdef} (a task's goal to draw and steer) and what they stand
 * on ({@code handsim.math}, {@code handsim.config}, {@code handsim.model}, {@code handsim.kin},
 * {@code handsim.sim}, {@code handsim.control}); never an engine, LWJGL, picocli or the app: the
 * viewer draws what a scene shows.
 */
package handsim.scene;
