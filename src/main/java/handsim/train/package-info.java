/**
 * Learning the throws: the physics tasks as {@link handsim.learn.Env environments} (one decision
 * per THROW, sec. 3.7), the learned throw policy the controller uses, training runs with their
 * run folders (DDPG's {@link handsim.train.TrainRun}, DAgger's {@link handsim.train.DaggerRun}
 * with its twin-world teacher), and the shipped policies. It joins {@code handsim.task} (episodes, tasks) and
 * {@code handsim.learn} (DDPG, CMA-ES), which do not know each other.
 */
package handsim.train;
