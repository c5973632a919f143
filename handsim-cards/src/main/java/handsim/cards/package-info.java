/**
 * The thesis' second system (sec. 3.2, 4.2): soft tetrahedral fingertips, driven by rigid bones,
 * handle thin-shell playing cards through IPC contact that never lets surfaces pass through each
 * other. Subpackages, from the bottom up: {@code geom} (contact kernels), {@code linalg} (dense
 * and sparse algebra), {@code mesh} (cards and fingertips), {@code energy} (elastic energies),
 * {@code contact} (barrier, friction, CCD), {@code sim} (scenes, state, implicit Euler), {@code
 * sleight} (Card Snapping). Nothing here imports ode4j, DL4J, LWJGL or picocli.
 *
 * <p>Its subpackages import each other, {@code handsim.config} (JSON configs) and {@code
 * handsim.report} (charts, atomic files); nothing else of handsim.
 */
package handsim.cards;
