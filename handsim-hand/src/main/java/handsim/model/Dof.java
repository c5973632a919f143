package handsim.model;

import handsim.math.Vec3;

/**
 * One degree of freedom: a rotation about {@code axis} (unit, parent frame of the zero
 * configuration) by an angle in [{@code lower}, {@code upper}] radians, driven by a PD torque
 * clamped to [{@code torqueMin}, {@code torqueMax}] N m (human strength; {@code torqueMin < 0}), and
 * resisted by the joint's passive viscosity {@code passiveDamping} (N m s/rad): the damping of
 * muscle and tissue that acts whatever the controller does.
 *
 * @param index position in the model's DOF vector
 * @param joint index of the joint this DOF belongs to
 * @param slot position of this DOF within its joint (0 = nearest the parent)
 */
public record Dof(int index, String name, int joint, int slot, Vec3 axis, double lower, double upper,
        double torqueMin, double torqueMax, double passiveDamping) {

    /** Clamps a torque to the DOF's strength. */
    public double clampTorque(double tau) {
        return Math.max(torqueMin, Math.min(torqueMax, tau));
    }

    /** |tau| relative to the limit in its direction (1 = at the limit). */
    public double torqueRatio(double tau) {
        return tau >= 0 ? tau / torqueMax : tau / torqueMin;
    }

    public double clamp(double angle) {
        return Math.max(lower, Math.min(upper, angle));
    }

    /** How far {@code angle} lies outside the limits (0 inside). */
    public double limitExcess(double angle) {
        return Math.max(0, Math.max(lower - angle, angle - upper));
    }
}
