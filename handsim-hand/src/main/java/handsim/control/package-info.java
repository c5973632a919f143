/**
 * The nominal controller of the paper, engine-free: PD joint control (eq. 3-4), the finite
 * state machine with Hermite palm trajectories (eq. 1) and SLERP rotations, damped least squares
 * IK (eq. 2), hand poses, catch planning and the throw-parameter vector the learner sets.
 * Everything here is a function of an observation and explicit controller state.
 *
 * <p>Imports {@code handsim.math}, {@code handsim.config}, {@code handsim.model}, {@code
 * handsim.kin} and {@code handsim.sim} (states and object specs, never an engine).
 */
package handsim.control;
