package handsim.sim;

import handsim.math.Quat;
import handsim.math.Vec3;

/**
 * Position and velocity of a rigid body's centre of mass, orientation, and angular velocity, all
 * in world coordinates.
 */
public record RigidState(Vec3 position, Quat orientation, Vec3 velocity, Vec3 angularVelocity) {

    public static RigidState at(Vec3 position, Vec3 velocity) {
        return new RigidState(position, Quat.IDENTITY, velocity, Vec3.ZERO);
    }

    public boolean isFinite() {
        return position.isFinite() && orientation.isFinite() && velocity.isFinite() && angularVelocity.isFinite();
    }
}
