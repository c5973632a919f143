/**
 * The command line ({@code scripts/handsim SUBCOMMAND}): one picocli command per subcommand, the
 * options they share declared once as mixins ({@link handsim.app.ControllerOptions}, {@link
 * handsim.app.EpisodeOptions}, {@link handsim.app.SceneOptions}), the wiring that loads the
 * shipped model and configs and chooses the engine ({@link handsim.app.Wiring}), run folders,
 * output paths and provenance. A command checks its options, wires the packages below and writes
 * what they return; the work itself lives in those packages.
 *
 * <p>The only package that imports picocli, and the only one that chooses an engine ({@code
 * handsim.sim.ode}) and the viewer; it may import every handsim package, and none imports it.
 */
package handsim.app;
