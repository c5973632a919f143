/**
 * Parallel rollouts, the one way handsim runs independent work in parallel: evaluation and
 * training episodes, benchmark loops, the learner's episodes on its environments and CMA-ES
 * searches, spread over worker threads, each worker with a resource of its own (a simulator, an
 * environment). A rollout is a function of its index alone (its seed comes from the index, and
 * it resets what it runs on), so the results are the same whatever the number of workers; they
 * come back in index order.
 *
 * <pre>{@code
 * try (Rollouts<Simulator> rollouts = new LocalRollouts<>(LocalRollouts.localCores(),
 *         () -> IsolatedEngine.simulator(model, simConfig))) {
 *     List<EpisodeResult> results = rollouts.run(episodes, sim -> {
 *         CatchEvaluation evaluation = ...;           // per worker: it holds mutable goals
 *         return i -> evaluation.run(sim, seed + i, loops, null);
 *     });
 * }
 * }</pre>
 *
 * Workers of one JVM must not share engine state: ode4j's statics (its random generator above
 * all) are per class loader, hence {@code handsim.sim.ode.IsolatedEngine}. A stop request
 * ({@code handsim.report.Stop}: SIGTERM, SIGINT) ends a run at once, leaving the rollouts under
 * way to their workers.
 *
 * <p>The same work runs on a cluster ({@link handsim.rollout.RemoteRollouts} over {@link
 * handsim.rollout.RemoteCalls}, whose engine a {@link handsim.rollout.RemoteBackend} found by
 * ServiceLoader provides): a run travels as a {@link handsim.rollout.PortableTask}, serialisable
 * data from which an executor rebuilds the task and its worker's resource, and results come back
 * as JSON that reads back bit for bit, so they are the thread pool's.
 *
 * <p>Imports {@code handsim.config} (JSON) and {@code handsim.report} and nothing else of handsim:
 * what a worker owns is a type parameter.
 */
package handsim.rollout;
