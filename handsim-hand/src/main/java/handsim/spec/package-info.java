/**
 * A run's resolved configuration of the arm and hand: {@link handsim.spec.RunConfigs} parses each
 * document of a {@link handsim.config.ConfigSet} once (the model, the physics, the controller,
 * the tasks' definitions of {@code handsim.taskdef}, the planner, the evaluation's settings) and
 * hands the parts down; the set itself is what a run records to be repeated.
 *
 * <p>Imports {@code handsim.config}, {@code handsim.model}, {@code handsim.kin}, {@code handsim.sim},
 * {@code handsim.control}, {@code handsim.task}, {@code handsim.taskdef}, {@code
 * handsim.planning} and {@code handsim.evaluation}; never an engine, DL4J, LWJGL or the app.
 */
package handsim.spec;
