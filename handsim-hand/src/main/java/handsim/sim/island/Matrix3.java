package handsim.sim.island;

/** 3x3 matrices (row-major, 9 numbers at an offset) and vectors (3 at an offset), in place. */
final class Matrix3 {

    private Matrix3() {
    }

    /** out = m v. */
    static void multiply(double[] m, int mi, double[] v, int vi, double[] out, int oi) {
        double x = v[vi], y = v[vi + 1], z = v[vi + 2];
        out[oi] = m[mi] * x + m[mi + 1] * y + m[mi + 2] * z;
        out[oi + 1] = m[mi + 3] * x + m[mi + 4] * y + m[mi + 5] * z;
        out[oi + 2] = m[mi + 6] * x + m[mi + 7] * y + m[mi + 8] * z;
    }

    /** out = a b (out must not overlap a or b). */
    static void multiply3(double[] a, int ai, double[] b, int bi, double[] out, int oi) {
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                out[oi + 3 * r + c] = a[ai + 3 * r] * b[bi + c] + a[ai + 3 * r + 1] * b[bi + 3 + c] + a[ai + 3 * r + 2] * b[bi + 6 + c];
            }
        }
    }

    /** out = r t r^T, the tensor t of a body frame in the world frame; {@code scratch} holds 9. */
    static void rotateTensor(double[] r, int ri, double[] t, int ti, double[] out, int oi, double[] scratch) {
        // scratch = t r^T
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                scratch[3 * i + j] = t[ti + 3 * i] * r[ri + 3 * j] + t[ti + 3 * i + 1] * r[ri + 3 * j + 1] + t[ti + 3 * i + 2] * r[ri + 3 * j + 2];
            }
        }
        multiply3(r, ri, scratch, 0, out, oi);
    }

    /** out = m^-1 by the adjugate; returns the determinant, and leaves out untouched when it is 0. */
    static double invert(double[] m, int mi, double[] out, int oi) {
        double m00 = m[mi], m01 = m[mi + 1], m02 = m[mi + 2];
        double m10 = m[mi + 3], m11 = m[mi + 4], m12 = m[mi + 5];
        double m20 = m[mi + 6], m21 = m[mi + 7], m22 = m[mi + 8];
        double det = m00 * (m11 * m22 - m12 * m21) - m01 * (m10 * m22 - m12 * m20) + m02 * (m10 * m21 - m11 * m20);
        if (det == 0) {
            return 0;
        }
        double k = 1 / det;
        out[oi] = (m11 * m22 - m12 * m21) * k;
        out[oi + 1] = (m21 * m02 - m01 * m22) * k;
        out[oi + 2] = (m01 * m12 - m11 * m02) * k;
        out[oi + 3] = (m12 * m20 - m10 * m22) * k;
        out[oi + 4] = (m00 * m22 - m20 * m02) * k;
        out[oi + 5] = (m10 * m02 - m00 * m12) * k;
        out[oi + 6] = (m10 * m21 - m20 * m11) * k;
        out[oi + 7] = (m20 * m01 - m00 * m21) * k;
        out[oi + 8] = (m00 * m11 - m01 * m10) * k;
        return det;
    }

    /** The rotation matrix of the unit quaternion (w, x, y, z) at {@code qi}. */
    static void fromQuaternion(double[] q, int qi, double[] out, int oi) {
        double q0 = q[qi], q1 = q[qi + 1], q2 = q[qi + 2], q3 = q[qi + 3];
        double qq1 = 2 * q1 * q1, qq2 = 2 * q2 * q2, qq3 = 2 * q3 * q3;
        out[oi] = 1 - qq2 - qq3;
        out[oi + 1] = 2 * (q1 * q2 - q0 * q3);
        out[oi + 2] = 2 * (q1 * q3 + q0 * q2);
        out[oi + 3] = 2 * (q1 * q2 + q0 * q3);
        out[oi + 4] = 1 - qq1 - qq3;
        out[oi + 5] = 2 * (q2 * q3 - q0 * q1);
        out[oi + 6] = 2 * (q1 * q3 - q0 * q2);
        out[oi + 7] = 2 * (q2 * q3 + q0 * q1);
        out[oi + 8] = 1 - qq1 - qq2;
    }

    /**
     * Two unit vectors p, q (at {@code pi}, {@code qi} of {@code out}) perpendicular to the unit
     * vector n and to each other, q = n x p; p is taken in the y-z plane when n is nearest the
     * z axis, else in the x-y plane, the same basis ODE's dPlaneSpace builds.
     */
    static void planeSpace(double nx, double ny, double nz, double[] out, int pi, int qi) {
        if (Math.abs(nz) > 0.7071067811865476) {
            double a = ny * ny + nz * nz;
            double k = 1 / Math.sqrt(a);
            out[pi] = 0;
            out[pi + 1] = -nz * k;
            out[pi + 2] = ny * k;
            out[qi] = a * k;
            out[qi + 1] = -nx * out[pi + 2];
            out[qi + 2] = nx * out[pi + 1];
        } else {
            double a = nx * nx + ny * ny;
            double k = 1 / Math.sqrt(a);
            out[pi] = -ny * k;
            out[pi + 1] = nx * k;
            out[pi + 2] = 0;
            out[qi] = -nz * out[pi + 1];
            out[qi + 1] = nz * out[pi];
            out[qi + 2] = a * k;
        }
    }
}
