/**
 * The engine-neutral simulation interface: {@link handsim.sim.Simulator} steps an arm+hand and
 * one thrown object, reads joint angles through {@link handsim.kin.Kinematics}, applies joint
 * torques, and reports hand-object contacts. Configuration ({@link handsim.sim.SimConfig}) and
 * the thrown objects ({@link handsim.sim.ObjectSpec}) live here too. The only implementation,
 * on ode4j, is in {@code handsim.sim.ode}.
 *
 * <p>Imports {@code handsim.math}, {@code handsim.config}, {@code handsim.model} and {@code
 * handsim.kin}; never an engine.
 */
package handsim.sim;
