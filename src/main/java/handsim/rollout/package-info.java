/**
 * Parallel rollouts: many independent simulations (evaluation episodes, training episodes,
 * benchmark loops) spread over worker threads, each worker with a simulator of its own. A
 * rollout is a function of its index alone (its seed comes from the index, and it resets the
 * simulator), so the results are the same whatever the number of workers; they come back in
 * index order.
 *
 * <pre>{@code
 * try (Rollouts rollouts = new LocalRollouts(LocalRollouts.localCores(),
 *         () -> IsolatedEngine.simulator(model, simConfig))) {
 *     List<EpisodeResult> results = rollouts.run(episodes, sim -> {
 *         CatchEvaluation evaluation = ...;           // per worker: it holds mutable goals
 *         return i -> evaluation.run(sim, seed + i, loops, null);
 *     });
 * }
 * }</pre>
 *
 * Workers of one JVM must not share engine state: ode4j's statics (its random generator above
 * all) are per class loader, hence {@link handsim.sim.ode.IsolatedEngine}.
 */
package handsim.rollout;
