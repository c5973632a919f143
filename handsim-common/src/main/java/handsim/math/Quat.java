package handsim.math;

/**
 * An immutable rotation quaternion (w, x, y, z). Operations assume unit length unless noted;
 * {@link #normalized()} restores it after accumulated round-off.
 */
public record Quat(double w, double x, double y, double z) {

    public static final Quat IDENTITY = new Quat(1, 0, 0, 0);

    /** Rotation by {@code angle} radians about the unit vector {@code axis}. */
    public static Quat fromAxisAngle(Vec3 axis, double angle) {
        double h = 0.5 * angle;
        double s = Math.sin(h);
        return new Quat(Math.cos(h), axis.x() * s, axis.y() * s, axis.z() * s);
    }

    /** Rotation from a rotation vector (axis times angle, radians). */
    public static Quat fromRotationVector(Vec3 r) {
        double angle = r.norm();
        if (angle < 1e-12) {
            return new Quat(1, 0.5 * r.x(), 0.5 * r.y(), 0.5 * r.z()).normalized();
        }
        return fromAxisAngle(r.times(1.0 / angle), angle);
    }

    /**
     * The rotation whose columns are the given orthonormal frame axes, i.e. that maps the world
     * axes X, Y, Z onto {@code ex, ey, ez}.
     */
    public static Quat fromFrame(Vec3 ex, Vec3 ey, Vec3 ez) {
        double m00 = ex.x(), m10 = ex.y(), m20 = ex.z();
        double m01 = ey.x(), m11 = ey.y(), m21 = ey.z();
        double m02 = ez.x(), m12 = ez.y(), m22 = ez.z();
        double trace = m00 + m11 + m22;
        Quat q;
        if (trace > 0) {
            double s = 0.5 / Math.sqrt(trace + 1.0);
            q = new Quat(0.25 / s, (m21 - m12) * s, (m02 - m20) * s, (m10 - m01) * s);
        } else if (m00 > m11 && m00 > m22) {
            double s = 2.0 * Math.sqrt(1.0 + m00 - m11 - m22);
            q = new Quat((m21 - m12) / s, 0.25 * s, (m01 + m10) / s, (m02 + m20) / s);
        } else if (m11 > m22) {
            double s = 2.0 * Math.sqrt(1.0 + m11 - m00 - m22);
            q = new Quat((m02 - m20) / s, (m01 + m10) / s, 0.25 * s, (m12 + m21) / s);
        } else {
            double s = 2.0 * Math.sqrt(1.0 + m22 - m00 - m11);
            q = new Quat((m10 - m01) / s, (m02 + m20) / s, (m12 + m21) / s, 0.25 * s);
        }
        return q.normalized().canonical();
    }

    /** The shortest rotation taking unit vector {@code from} onto unit vector {@code to}. */
    public static Quat between(Vec3 from, Vec3 to) {
        double d = from.dot(to);
        if (d < -1 + 1e-12) {
            return fromAxisAngle(from.anyPerpendicular(), Math.PI);
        }
        Vec3 c = from.cross(to);
        return new Quat(1 + d, c.x(), c.y(), c.z()).normalized();
    }

    /** Hamilton product {@code this * o}: apply {@code o} first, then this. */
    public Quat mul(Quat o) {
        return new Quat(
                w * o.w - x * o.x - y * o.y - z * o.z,
                w * o.x + x * o.w + y * o.z - z * o.y,
                w * o.y - x * o.z + y * o.w + z * o.x,
                w * o.z + x * o.y - y * o.x + z * o.w);
    }

    public Quat conjugate() {
        return new Quat(w, -x, -y, -z);
    }

    /** Rotates {@code v} by this quaternion. */
    public Vec3 rotate(Vec3 v) {
        // v' = v + 2w (u x v) + 2 u x (u x v), u = (x, y, z)
        double tx = 2 * (y * v.z() - z * v.y());
        double ty = 2 * (z * v.x() - x * v.z());
        double tz = 2 * (x * v.y() - y * v.x());
        return new Vec3(
                v.x() + w * tx + (y * tz - z * ty),
                v.y() + w * ty + (z * tx - x * tz),
                v.z() + w * tz + (x * ty - y * tx));
    }

    /** Rotates {@code v} by the inverse of this quaternion. */
    public Vec3 inverseRotate(Vec3 v) {
        return conjugate().rotate(v);
    }

    public double dot(Quat o) {
        return w * o.w + x * o.x + y * o.y + z * o.z;
    }

    public double norm() {
        return Math.sqrt(w * w + x * x + y * y + z * z);
    }

    public Quat normalized() {
        double n = norm();
        if (n < 1e-12) {
            throw new ArithmeticException("cannot normalize a zero quaternion");
        }
        return new Quat(w / n, x / n, y / n, z / n);
    }

    /** The same rotation with {@code w >= 0}. */
    public Quat canonical() {
        return w < 0 ? new Quat(-w, -x, -y, -z) : this;
    }

    /** Rotation vector (axis times angle in [0, pi]) of this rotation. */
    public Vec3 toRotationVector() {
        Quat q = canonical();
        double s = Math.sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
        if (s < 1e-12) {
            return new Vec3(2 * q.x, 2 * q.y, 2 * q.z);
        }
        double angle = 2 * Math.atan2(s, q.w);
        double k = angle / s;
        return new Vec3(q.x * k, q.y * k, q.z * k);
    }

    /** Rotation angle in [0, pi]. */
    public double angle() {
        return toRotationVector().norm();
    }

    /** Angle in [0, pi] of the rotation taking this onto {@code o}. */
    public double angleTo(Quat o) {
        double d = Math.min(1.0, Math.abs(dot(o)));
        return 2 * Math.acos(d);
    }

    /** The image of the world X axis: the first column of the rotation matrix. */
    public Vec3 xAxis() {
        return new Vec3(1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y));
    }

    /** The image of the world Y axis. */
    public Vec3 yAxis() {
        return new Vec3(2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x));
    }

    /** The image of the world Z axis. */
    public Vec3 zAxis() {
        return new Vec3(2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y));
    }

    /**
     * Spherical linear interpolation from this ({@code s = 0}) to {@code o} ({@code s = 1})
     * along the shorter arc.
     */
    public Quat slerp(Quat o, double s) {
        double d = dot(o);
        Quat b = o;
        if (d < 0) {
            d = -d;
            b = new Quat(-o.w, -o.x, -o.y, -o.z);
        }
        if (d > 0.9995) {
            // nearly parallel: normalized lerp is accurate and avoids dividing by sin(~0)
            return new Quat(w + s * (b.w - w), x + s * (b.x - x), y + s * (b.y - y), z + s * (b.z - z))
                    .normalized();
        }
        double theta = Math.acos(d);
        double sinTheta = Math.sin(theta);
        double a0 = Math.sin((1 - s) * theta) / sinTheta;
        double a1 = Math.sin(s * theta) / sinTheta;
        return new Quat(a0 * w + a1 * b.w, a0 * x + a1 * b.x, a0 * y + a1 * b.y, a0 * z + a1 * b.z);
    }

    public boolean isFinite() {
        return Double.isFinite(w) && Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }

    @Override
    public String toString() {
        return String.format("(w %.6g, %.6g, %.6g, %.6g)", w, x, y, z);
    }
}
