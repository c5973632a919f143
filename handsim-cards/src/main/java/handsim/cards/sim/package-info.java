/**
 * Card scenes and their time stepping: the immutable {@link handsim.cards.sim.SoftWorld} built
 * from cards and fingertips, the copyable {@link handsim.cards.sim.SimState} (checkpoints restore
 * it bit for bit), bone control, configs/cards readers, and {@link handsim.cards.sim.SoftSimulator},
 * implicit Euler as an incremental potential minimised by projected Newton. Imports the other
 * {@code handsim.cards} packages and {@code handsim.config}.
 *
 * <p>Imports the other card packages, {@code handsim.config} and {@code handsim.report} at most;
 * nothing else of handsim.
 */
package handsim.cards.sim;
