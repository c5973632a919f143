package handsim.kin;

/**
 * Quaternion (w, x, y, z) and 3-vector arithmetic on {@code double[]} slots, for the per-step
 * paths that must not allocate. Each formula is written exactly as in {@link handsim.math.Quat}
 * and {@link handsim.math.Vec3}, operation for operation, so both give bit-identical results.
 * Outputs may not alias inputs. Used by {@link Kinematics} and by the engine adapter.
 */
public final class Rotations {

    private Rotations() {
    }

    /** {@code out[o..o+3] = a[i..i+3] * b[j..j+3]} (Hamilton product: b first, then a). */
    public static void mul(double[] a, int i, double[] b, int j, double[] out, int o) {
        double aw = a[i], ax = a[i + 1], ay = a[i + 2], az = a[i + 3];
        double bw = b[j], bx = b[j + 1], by = b[j + 2], bz = b[j + 3];
        out[o] = aw * bw - ax * bx - ay * by - az * bz;
        out[o + 1] = aw * bx + ax * bw + ay * bz - az * by;
        out[o + 2] = aw * by - ax * bz + ay * bw + az * bx;
        out[o + 3] = aw * bz + ax * by - ay * bx + az * bw;
    }

    /** {@code out[o..o+3] = conj(a[i..i+3]) * b[j..j+3]}: b relative to a. */
    public static void conjMul(double[] a, int i, double[] b, int j, double[] out, int o) {
        double aw = a[i], ax = -a[i + 1], ay = -a[i + 2], az = -a[i + 3];
        double bw = b[j], bx = b[j + 1], by = b[j + 2], bz = b[j + 3];
        out[o] = aw * bw - ax * bx - ay * by - az * bz;
        out[o + 1] = aw * bx + ax * bw + ay * bz - az * by;
        out[o + 2] = aw * by - ax * bz + ay * bw + az * bx;
        out[o + 3] = aw * bz + ax * by - ay * bx + az * bw;
    }

    /** {@code out[o..o+3]} = rotation by {@code angle} about the unit axis {@code axis[k..k+2]}. */
    public static void fromAxisAngle(double[] axis, int k, double angle, double[] out, int o) {
        double h = 0.5 * angle;
        double s = Math.sin(h);
        out[o] = Math.cos(h);
        out[o + 1] = axis[k] * s;
        out[o + 2] = axis[k + 1] * s;
        out[o + 3] = axis[k + 2] * s;
    }

    /** {@code out[o..o+2]} = the quaternion (w, x, y, z) applied to {@code v[k..k+2]}. */
    public static void rotate(double w, double x, double y, double z, double[] v, int k, double[] out, int o) {
        double vx = v[k], vy = v[k + 1], vz = v[k + 2];
        // v' = v + 2w (u x v) + 2 u x (u x v), u = (x, y, z)
        double tx = 2 * (y * vz - z * vy);
        double ty = 2 * (z * vx - x * vz);
        double tz = 2 * (x * vy - y * vx);
        out[o] = vx + w * tx + (y * tz - z * ty);
        out[o + 1] = vy + w * ty + (z * tx - x * tz);
        out[o + 2] = vz + w * tz + (x * ty - y * tx);
    }

    /**
     * {@code u[j..j+2] . R v[k..k+2]} for the quaternion (w, x, y, z): {@link #rotate} then
     * {@link #dot}, the same operations, without an output buffer.
     */
    public static double rotateDot(double w, double x, double y, double z, double[] v, int k, double[] u, int j) {
        double vx = v[k], vy = v[k + 1], vz = v[k + 2];
        double tx = 2 * (y * vz - z * vy);
        double ty = 2 * (z * vx - x * vz);
        double tz = 2 * (x * vy - y * vx);
        double rx = vx + w * tx + (y * tz - z * ty);
        double ry = vy + w * ty + (z * tx - x * tz);
        double rz = vz + w * tz + (x * ty - y * tx);
        return u[j] * rx + u[j + 1] * ry + u[j + 2] * rz;
    }

    /** {@code out[o..o+2]} = the quaternion {@code q[i..i+3]} applied to {@code v[k..k+2]}. */
    public static void rotate(double[] q, int i, double[] v, int k, double[] out, int o) {
        rotate(q[i], q[i + 1], q[i + 2], q[i + 3], v, k, out, o);
    }

    /** {@code out[o..o+2]} = the inverse of {@code q[i..i+3]} applied to {@code v[k..k+2]}. */
    public static void inverseRotate(double[] q, int i, double[] v, int k, double[] out, int o) {
        rotate(q[i], -q[i + 1], -q[i + 2], -q[i + 3], v, k, out, o);
    }

    public static double dot(double[] a, int i, double[] b, int j) {
        return a[i] * b[j] + a[i + 1] * b[j + 1] + a[i + 2] * b[j + 2];
    }

    /** {@code out[o..o+2] = a[i..i+2] x b[j..j+2]}. */
    public static void cross(double[] a, int i, double[] b, int j, double[] out, int o) {
        double ax = a[i], ay = a[i + 1], az = a[i + 2];
        double bx = b[j], by = b[j + 1], bz = b[j + 2];
        out[o] = ay * bz - az * by;
        out[o + 1] = az * bx - ax * bz;
        out[o + 2] = ax * by - ay * bx;
    }
}
