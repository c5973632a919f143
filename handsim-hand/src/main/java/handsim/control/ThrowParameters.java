package handsim.control;

import handsim.math.Vec3;

/**
 * The parameters of one THROW, the action of the learning agent (sec. 3.7):
 *
 * @param dOffset palm displacement over the THROW state, world frame (m): its direction is the
 *     throwing direction and, with the state's duration, its length sets the release speed
 * @param rTarget final palm rotation of THROW relative to the neutral palm rotation, as a
 *     rotation vector in world axes (rad)
 * @param tOpen time after the THROW began at which the hand starts to open (s)
 */
public record ThrowParameters(Vec3 dOffset, Vec3 rTarget, double tOpen) {

    /** Number of scalars in the vector form. */
    public static final int SIZE = 7;

    /** The vector form (dOffset, rTarget, tOpen). */
    public double[] toArray() {
        return new double[] {dOffset.x(), dOffset.y(), dOffset.z(), rTarget.x(), rTarget.y(), rTarget.z(), tOpen};
    }

    public static ThrowParameters fromArray(double[] a) {
        if (a.length != SIZE) {
            throw new IllegalArgumentException("a throw-parameter vector has " + SIZE + " entries, got " + a.length);
        }
        return new ThrowParameters(new Vec3(a[0], a[1], a[2]), new Vec3(a[3], a[4], a[5]), a[6]);
    }

    /** Linear interpolation between two parameter sets. */
    public ThrowParameters lerp(ThrowParameters o, double s) {
        return new ThrowParameters(dOffset.lerp(o.dOffset, s), rTarget.lerp(o.rTarget, s), tOpen + s * (o.tOpen - tOpen));
    }

    public boolean isFinite() {
        return dOffset.isFinite() && rTarget.isFinite() && Double.isFinite(tOpen);
    }
}
