/**
 * Card sleights as functions of their bone trajectories: Card Snapping (thesis 4.2.4), its scene,
 * parameters, {@link handsim.cards.sleight.SnapTrial#run}, the entry point an optimiser calls, and
 * {@link handsim.cards.sleight.SnapStudy}, the trial as a study's objective. Imports
 * {@code handsim.cards.sim}, {@code handsim.cards.mesh}, {@code handsim.cards.study},
 * {@code handsim.cards.tpe} and {@code handsim.config}.
 */
package handsim.cards.sleight;
