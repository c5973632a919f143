/**
 * Learning, with no physics: the {@link handsim.learn.Env} interface a task implements (one
 * decision per step, terminal vs truncated ends), DDPG on deeplearning4j (Lillicrap et al. 2015,
 * the learner of paper sec. 3.7), its replay buffer, exploration noise and observation
 * normaliser, whole-agent checkpoints, the training driver and its metrics, the plain-Java
 * {@link handsim.learn.Policy} that is shipped and evaluated, CMA-ES (Hansen 2006) and actor
 * pretraining by regression for the imitation warm start of sec. 4.4, and imitation of a teacher
 * by dataset aggregation ({@link handsim.learn.Dagger} over a {@link handsim.learn.TeachableEnv},
 * its dataset on disk {@link handsim.learn.DemonstrationSet}).
 *
 * <p>Actions are always in [-1, 1]^k (the actor's tanh range); each task maps them onto its
 * own parameter box (see {@code handsim.control.ThrowSpace}). Imports {@code handsim.config}
 * (its JSON configs), {@code handsim.report} (curves, atomic files), {@code handsim.rollout}
 * (episodes on parallel workers), deeplearning4j and nd4j; never ode4j, LWJGL or picocli, and
 * nothing of the tasks: it sees a task only through {@link handsim.learn.Env}.
 *
 * <p>How a task plugs in (the throw tasks, for example): its {@code Env} observes the hand and
 * object state plus the goal (sec. 3.7), turns the action into {@code ThrowParameters} with
 * {@code ThrowSpace.fromAction}, simulates until the next throw is due, and returns the reward
 * of eq. (5)-(7), {@code terminal} when the object is dropped and {@code truncated} at the loop
 * cap. Then
 * <pre>
 * LearnerConfig c = LearnerConfig.load(Path.of("configs/train/ddpg-defaults.json"));
 * Trainer t = Trainer.create(c, env.observationSize(), env.actionSize());   // or Trainer.resume(checkpoint)
 * try (MetricsCsv csv = MetricsCsv.open(runDir.resolve("metrics.csv"), t.episodes())) {
 *     t.train(env, null, csv, runDir.resolve("checkpoint.zip"));   // or in rounds on rollout workers: EpisodePlayer.onWorkers
 * }
 * LearningCurves.plotRewards(runDir.resolve("rewards.png"), MetricsCsv.read(...), "height task");
 * t.agent().policy("height task, seed 1", "ThrowSpace of configs/controller.json").save(policyFile);
 * </pre>
 */
package handsim.learn;
