/**
 * Drawing: the only package that uses LWJGL (GLFW, OpenGL). It reads {@link
 * handsim.sim.WorldSnapshot}s and never steps the simulation; the same loops run headless.
 */
package handsim.viewer;
