package handsim.sim.island;

import handsim.math.ArcTangent;

/**
 * The joint angles a hinge's and a universal joint's stops are tested with, measured as ODE
 * measures them, so that a stop engages exactly when ode4j's would: from the relative rotation
 * of the two bodies, a quaternion (w, v), the angle 2 atan2(|v|, w) signed by v along the axis
 * (for a universal joint, relative to the "cross" frame spanned by its two world axes). Near
 * zero angle this reads a joint's small misalignment as angle, which a stop at zero (a finger
 * lying open) feels. Quaternions are (w, x, y, z); scratch space is the caller's.
 */
final class JointAngles {

    private JointAngles() {
    }

    /** out = a b, each optionally conjugated first (all at offsets of 4-arrays). */
    static void multiply(double[] a, int ai, boolean conjA, double[] b, int bi, boolean conjB, double[] out, int oi) {
        double sa = conjA ? -1 : 1, sb = conjB ? -1 : 1;
        double a0 = a[ai], a1 = sa * a[ai + 1], a2 = sa * a[ai + 2], a3 = sa * a[ai + 3];
        double b0 = b[bi], b1 = sb * b[bi + 1], b2 = sb * b[bi + 2], b3 = sb * b[bi + 3];
        out[oi] = a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3;
        out[oi + 1] = a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2;
        out[oi + 2] = a0 * b2 + a2 * b0 + a3 * b1 - a1 * b3;
        out[oi + 3] = a0 * b3 + a3 * b0 + a1 * b2 - a2 * b1;
    }

    /**
     * The relative rotation q (at {@code qi}) seen about {@code axis} (at {@code ai}, in the frame
     * q is expressed in): into {@code out} at {@code oi} the sine of the half angle |v| and the
     * cosine w, negated when v points away from the axis (which keeps the angle's sign).
     */
    static void aboutAxis(double[] q, int qi, double[] axis, int ai, double[] out, int oi) {
        double w = q[qi], x = q[qi + 1], y = q[qi + 2], z = q[qi + 3];
        out[oi] = Math.sqrt(x * x + y * y + z * z);
        out[oi + 1] = x * axis[ai] + y * axis[ai + 1] + z * axis[ai + 2] >= 0 ? w : -w;
    }

    /**
     * The angle of a rotation given by {@link #aboutAxis}, in [-pi, pi), with ODE's sign (the
     * engine's axis turns the second body by minus the angle); atan2 with Math.atan2's bits.
     */
    static double angle(double sinHalf, double cosHalf) {
        double theta = 2 * ArcTangent.atan2(sinHalf, cosHalf);
        if (theta > Math.PI) {
            theta -= 2 * Math.PI;
        }
        return -theta;
    }

    /**
     * tan(angle / 2) of a rotation given by {@link #aboutAxis}, which grows with the angle on
     * (-pi, pi): stops are tested by it without the arc tangent.
     */
    static double halfTangent(double sinHalf, double cosHalf) {
        return -sinHalf / cosHalf;
    }

    /** A hinge's rotation about its axis (see {@link #aboutAxis}): the child's relative to the parent about the parent-frame axis. */
    static void hinge(double[] q1, int i1, double[] q2, int i2, double[] axis, int ai, double[] s, double[] out, int oi) {
        multiply(q1, i1, true, q2, i2, false, s, 0);
        aboutAxis(s, 0, axis, ai, out, oi);
    }

    /**
     * The quaternion of the rotation whose columns are a (normalised), b made perpendicular to it
     * and normalised, and a x b: the cross frame of a universal joint's two axes. Returns false,
     * out untouched, for a zero or parallel pair.
     */
    static boolean crossFrame(double ax, double ay, double az, double bx, double by, double bz, double[] out, int oi) {
        double l = Math.sqrt(ax * ax + ay * ay + az * az);
        if (l <= 0) {
            return false;
        }
        l = 1 / l;
        ax *= l;
        ay *= l;
        az *= l;
        double k = ax * bx + ay * by + az * bz;
        bx -= k * ax;
        by -= k * ay;
        bz -= k * az;
        l = Math.sqrt(bx * bx + by * by + bz * bz);
        if (l <= 0) {
            return false;
        }
        l = 1 / l;
        bx *= l;
        by *= l;
        bz *= l;
        double cx = -by * az + ay * bz, cy = -bz * ax + az * bx, cz = -bx * ay + ax * by;
        // the rotation matrix (columns a, b, c) as a quaternion, from its largest diagonal term
        double tr = ax + by + cz;
        int largest = tr >= 0 ? -1 : by > ax ? (cz > by ? 2 : 1) : (cz > ax ? 2 : 0);
        double s;
        switch (largest) {
            case -1 -> {
                s = Math.sqrt(tr + 1);
                out[oi] = 0.5 * s;
                s = 0.5 / s;
                out[oi + 1] = (bz - cy) * s;
                out[oi + 2] = (cx - az) * s;
                out[oi + 3] = (ay - bx) * s;
            }
            case 0 -> {
                s = Math.sqrt((ax - (by + cz)) + 1);
                out[oi + 1] = 0.5 * s;
                s = 0.5 / s;
                out[oi + 2] = (bx + ay) * s;
                out[oi + 3] = (az + cx) * s;
                out[oi] = (bz - cy) * s;
            }
            case 1 -> {
                s = Math.sqrt((by - (cz + ax)) + 1);
                out[oi + 2] = 0.5 * s;
                s = 0.5 / s;
                out[oi + 3] = (cy + bz) * s;
                out[oi + 1] = (bx + ay) * s;
                out[oi] = (cx - az) * s;
            }
            default -> {
                s = Math.sqrt((cz - (ax + by)) + 1);
                out[oi + 3] = 0.5 * s;
                s = 0.5 / s;
                out[oi + 1] = (az + cx) * s;
                out[oi + 2] = (cy + bz) * s;
                out[oi] = (ay - bx) * s;
            }
        }
        return true;
    }

    /**
     * A universal joint's two rotations (see {@link #aboutAxis}) into {@code out} (4 numbers; the
     * second angle is minus that rotation's): each body's rotation relative to the cross frame
     * of the world axes {@code ax1}, {@code ax2} (at {@code wi} and {@code wi + 3}), referred to
     * the cross frames at rest ({@code rest}: 8 numbers, the frame of (axis1, axis2) then of
     * (axis2, axis1)), about each body's own axis ({@code axis1}, {@code axis2} in the body
     * frames); the second body's cross frame is the first turned half a turn about the bisector
     * of the axes. Returns false (both rotations zero) for parallel axes. {@code s} holds 16.
     */
    static boolean universal(double[] q1, int i1, double[] q2, int i2, double[] w, int wi, double[] rest, int ri,
            double[] axis1, double[] axis2, int ai, double[] out, double[] s) {
        if (!crossFrame(w[wi], w[wi + 1], w[wi + 2], w[wi + 3], w[wi + 4], w[wi + 5], s, 0)) {
            out[0] = out[2] = 0;
            out[1] = out[3] = 1;
            return false;
        }
        multiply(q1, i1, true, s, 0, false, s, 4);
        multiply(s, 4, false, rest, ri, true, s, 8);
        aboutAxis(s, 8, axis1, ai, out, 0);
        double bx = w[wi] + w[wi + 3], by = w[wi + 1] + w[wi + 4], bz = w[wi + 2] + w[wi + 5];
        double l = 1 / Math.sqrt(bx * bx + by * by + bz * bz);
        s[12] = 0;
        s[13] = bx * l;
        s[14] = by * l;
        s[15] = bz * l;
        multiply(s, 12, false, s, 0, false, s, 4);
        multiply(q2, i2, true, s, 4, false, s, 8);
        multiply(s, 8, false, rest, ri + 4, true, s, 0);
        aboutAxis(s, 0, axis2, ai, out, 2);
        return true;
    }
}
