/**
 * The ode4j implementation of {@link handsim.sim.Simulator}: the only package that imports
 * ode4j. Bodies and joints are built from the model in its zero configuration; joint angles are
 * read with {@link handsim.kin.Kinematics} and ball-joint limits enforced by user-mode angular
 * motors fed with those angles, so the engine, the IK and the PD agree on every angle.
 *
 * <p>The constrained step is ode4j's quickStep or handsim's own ({@code handsim.sim.island}),
 * which this package drives on ode4j's bodies with ode4j's contact geometry.
 *
 * <p>Imports ode4j (the only package that may), {@code handsim.math}, {@code handsim.model},
 * {@code handsim.kin}, {@code handsim.sim} and {@code handsim.sim.island}.
 */
package handsim.sim.ode;
