/**
 * Live runs: an {@link handsim.task.InteractiveScene} paced to the wall clock on a thread of its
 * own ({@link handsim.live.LiveRun}, with the sim-time accumulator {@link handsim.live.SimClock}),
 * publishing immutable {@link handsim.live.LiveFrame}s that a watcher reads. Nothing here draws
 * or knows who watches; nothing in the simulation or the controllers knows it exists.
 */
package handsim.live;
