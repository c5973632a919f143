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
 * way to their workers. Imports {@code handsim.report} only: what a worker owns is a type
 * parameter.
 */
package handsim.rollout;
