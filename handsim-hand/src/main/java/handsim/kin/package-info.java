/**
 * Forward kinematics, joint-angle decomposition and site Jacobians of a {@link
 * handsim.model.HandModel}, computed from the joint angle vector alone (no physics engine).
 * The engine adapter uses the same decomposition to read joint angles from body orientations,
 * so the controller, the IK and the simulation agree on what an angle means.
 *
 * <p>Imports {@code handsim.math} and {@code handsim.model} only.
 */
package handsim.kin;
