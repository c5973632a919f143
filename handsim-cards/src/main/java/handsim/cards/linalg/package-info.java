/**
 * Linear algebra of the card simulator: small dense symmetric eigen-decompositions and PSD
 * projection, the rotation-variant 3x3 SVD, and the sparse SPD Newton system (ojAlgo's LDLᵀ with
 * CSparseJ's AMD ordering). The only package that imports ojAlgo or CSparseJ.
 *
 * <p>Imports the other card packages, {@code handsim.config} and {@code handsim.report} at most;
 * nothing else of handsim.
 */
package handsim.cards.linalg;
