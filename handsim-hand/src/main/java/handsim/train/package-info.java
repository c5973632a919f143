/**
 * Learning the throws: the physics tasks as {@link handsim.learn.Env environments} (one decision
 * per THROW, sec. 3.7), the learned throw policy the controller uses, training runs with their
 * run folders (DDPG's {@link handsim.train.TrainRun}, DAgger's {@link handsim.train.DaggerRun}
 * with its twin-world teacher, {@code handsim.planning.ThrowTeacher}), and the shipped policies. It joins {@code handsim.task} (episodes, tasks) and
 * {@code handsim.learn} (DDPG, CMA-ES), which do not know each other.
 *
 * <p>Imports {@code handsim.math}, {@code handsim.config}, {@code handsim.sim} (the interface),
 * {@code handsim.control}, {@code handsim.task}, {@code handsim.evaluation} (seeded episodes),
 * {@code handsim.planning} (DAgger's teacher), {@code handsim.taskdef} (the tasks' run fields),
 * {@code handsim.rollout}, {@code handsim.learn} and {@code handsim.report}; never an engine,
 * LWJGL or picocli: the app wires the engine in.
 */
package handsim.train;
