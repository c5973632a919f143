/**
 * Drawing: the only package that uses LWJGL (GLFW, OpenGL). {@link handsim.viewer.SceneRenderer}
 * draws {@link handsim.sim.WorldSnapshot}s for both the off-screen frames of {@code render} and
 * the interactive {@link handsim.viewer.Viewer}, which shows the {@link handsim.scene.LiveFrame}s
 * of a live run with a heads-up display and forwards keys to it. Nothing here steps the
 * simulation; the same loops run headless. Settings: {@code configs/viewer.json}.
 */
package handsim.viewer;
