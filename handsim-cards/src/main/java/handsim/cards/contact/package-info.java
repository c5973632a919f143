/**
 * IPC contact for the card simulator (Li et al. 2020; Codim-IPC, Li et al. 2021): the log
 * barrier on thickness-offset squared distances, smoothed lagged friction, the spatial-hash broad
 * phase, the set of active contacts, and the largest intersection-free step of a Newton update.
 * Imports {@code handsim.cards.geom}, {@code handsim.cards.linalg} and {@code handsim.cards.mesh} only.
 *
 * <p>Imports the other card packages, {@code handsim.config} and {@code handsim.report} at most;
 * nothing else of handsim.
 */
package handsim.cards.contact;
