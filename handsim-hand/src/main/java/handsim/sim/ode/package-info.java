/**
 * The ode4j implementation of {@link handsim.sim.Simulator}: the only package that imports
 * ode4j. Bodies and joints are built from the model in its zero configuration; joint angles are
 * read with {@link handsim.kin.Kinematics} and ball-joint limits enforced by user-mode angular
 * motors fed with those angles, so the engine, the IK and the PD agree on every angle.
 *
 * <p>Imports ode4j (the only package that may), {@code handsim.math}, {@code handsim.model},
 * {@code handsim.kin} and {@code handsim.sim}.
 */
package handsim.sim.ode;
