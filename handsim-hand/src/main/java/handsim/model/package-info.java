/**
 * The immutable arm+hand model, loaded once from {@code models/*.json} and validated: bodies,
 * joints with their degrees of freedom, limits and torque limits, collision shapes, named sites
 * and the named hand poses. Names are resolved to indices here, once; everything downstream
 * looks bodies and joints up by name.
 *
 * <p>Frames: in the model's zero configuration (all joint angles 0, the anatomical position)
 * every body frame is aligned with the world frame and has its origin at the body's joint
 * anchor; shapes, centres of mass and joint axes are given in that frame.
 *
 * <p>Imports {@code handsim.math} and {@code handsim.config}; no engine.
 */
package handsim.model;
