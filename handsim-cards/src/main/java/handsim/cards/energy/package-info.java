/**
 * Elastic energies of the card simulator, element by element with gradients and (projected)
 * Hessians: the thin-shell membrane and hinge bending of the cards and the fixed-corotated
 * tetrahedra of the fingertips. Imports {@code handsim.cards.geom} and {@code handsim.cards.linalg} only.
 *
 * <p>Imports the other card packages, {@code handsim.config} and {@code handsim.report} at most;
 * nothing else of handsim.
 */
package handsim.cards.energy;
