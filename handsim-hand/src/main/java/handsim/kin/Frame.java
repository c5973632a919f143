package handsim.kin;

import handsim.math.Quat;
import handsim.math.Vec3;

/** A rigid transform: a frame with {@code origin} and {@code rotation} in world coordinates. */
public record Frame(Vec3 origin, Quat rotation) {

    public static final Frame IDENTITY = new Frame(Vec3.ZERO, Quat.IDENTITY);

    /** World coordinates of a point given in this frame. */
    public Vec3 pointToWorld(Vec3 local) {
        return origin.plus(rotation.rotate(local));
    }

    /** This frame's coordinates of a world point. */
    public Vec3 pointFromWorld(Vec3 world) {
        return rotation.inverseRotate(world.minus(origin));
    }

    /** The frame {@code local} (given relative to this one) in world coordinates. */
    public Frame compose(Frame local) {
        return new Frame(pointToWorld(local.origin), rotation.mul(local.rotation));
    }
}
