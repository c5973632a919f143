/**
 * Drawing: the only package that uses LWJGL (GLFW, OpenGL). {@link handsim.viewer.SceneRenderer}
 * draws {@link handsim.sim.WorldSnapshot}s for both the off-screen frames of {@code render} and
 * the interactive {@link handsim.viewer.Viewer}, which shows the {@link handsim.scene.LiveFrame}s
 * of a live run with a heads-up display and forwards keys to it. Nothing here steps the
 * simulation; the same loops run headless. Settings: {@code configs/viewer.json}.
 *
 * <p>Imports LWJGL (the only package that may), {@code handsim.math}, {@code handsim.config},
 * {@code handsim.model}, {@code handsim.kin}, {@code handsim.mesh}, {@code handsim.sim}
 * (snapshots), {@code handsim.task} (goals), {@code handsim.scene}, {@code handsim.export} and
 * {@code handsim.report}; it draws what a scene shows and never steps physics.
 */
package handsim.viewer;
