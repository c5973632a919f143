/**
 * Parallel rollouts: many independent simulations (evaluation episodes, training episodes,
 * benchmark loops) spread over worker threads, each worker with a simulator of its own. A
 * rollout is a function of its index alone (its seed comes from the index), so the results are
 * the same whatever the number of workers; they come back in index order.
 */
package handsim.rollout;
