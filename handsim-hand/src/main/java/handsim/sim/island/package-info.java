/**
 * handsim's own island step: one time step of rigid bodies joined by the arm's joints and by
 * contacts, in the formulation of ODE's quickStep (Smith's Open Dynamics Engine, as ode4j 0.5.3
 * steps it): constraint rows with ERP/CFM, a projected Gauss-Seidel solve with successive
 * over-relaxation, Coulomb friction bounded by the normal impulse, and semi-implicit Euler
 * integration. Everything is held in flat arrays sized once and reused, so a step allocates
 * nothing; nothing is static, so every world steps on its own, random row order included.
 *
 * <p>The bodies, joints and contact points come in as numbers (positions, quaternions, anchors,
 * axes, contact geometry): this package knows no engine and no model. {@code handsim.sim.ode}
 * fills it from ode4j's bodies and contact geometry and writes the result back.
 *
 * <p>Imports {@code handsim.math} only (its arc tangent, {@code ArcTangent}).
 */
package handsim.sim.island;
