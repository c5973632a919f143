/**
 * Card sleights as functions of their bone trajectories: Card Snapping (thesis 4.2.4), its scene,
 * parameters, {@link handsim.cards.sleight.SnapTrial#run}, the entry point an optimiser calls, and
 * {@link handsim.cards.sleight.SnapStudy}, the trial as a study's objective
 * ({@link handsim.cards.sleight.SnapObjective}: in the form that travels to a cluster).
 *
 * <p>Imports the other card packages, {@code handsim.config} and {@code handsim.report} at most;
 * nothing else of handsim.
 */
package handsim.cards.sleight;
