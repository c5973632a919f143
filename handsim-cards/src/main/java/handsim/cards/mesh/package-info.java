/**
 * Meshes of the card simulator: the playing card's triangulated mid-surface ({@link
 * handsim.cards.mesh.CardMesher}), the tetrahedral fingertip ellipsoid with its bone nodes
 * ({@link handsim.cards.mesh.FingertipMesher}), and the mesh types with their derived edges,
 * hinges and boundary surfaces. Pure Java: imports nothing outside the JDK.
 *
 * <p>Imports the other card packages, {@code handsim.config} and {@code handsim.report} at most;
 * nothing else of handsim.
 */
package handsim.cards.mesh;
