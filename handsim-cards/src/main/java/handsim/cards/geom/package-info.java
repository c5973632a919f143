/**
 * Contact geometry of the soft-body card simulator: squared distances between points, edges and
 * triangles with their closest-feature types, gradients and Hessians; the hinge (dihedral) angle;
 * the edge–edge mollifier; additive continuous collision detection; and {@link
 * handsim.cards.geom.Jet}, the small forward-mode AD the shell energies use. Pure Java: imports
 * nothing outside the JDK.
 *
 * <p>Imports the other card packages, {@code handsim.config} and {@code handsim.report} at most;
 * nothing else of handsim.
 */
package handsim.cards.geom;
