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

    /** out = r t r^T, the tensor t of a body frame in the world frame, r given by its rows (r0 r1 r2; r3 r4 r5; r6 r7 r8). */
    static void rotateTensor(double r0, double r1, double r2, double r3, double r4, double r5, double r6, double r7, double r8,
            double[] t, int ti, double[] out, int oi) {
        // s = t r^T
        double t0 = t[ti], t1 = t[ti + 1], t2 = t[ti + 2], t3 = t[ti + 3], t4 = t[ti + 4], t5 = t[ti + 5], t6 = t[ti + 6], t7 = t[ti + 7],
                t8 = t[ti + 8];
        double s0 = t0 * r0 + t1 * r1 + t2 * r2, s1 = t0 * r3 + t1 * r4 + t2 * r5, s2 = t0 * r6 + t1 * r7 + t2 * r8;
        double s3 = t3 * r0 + t4 * r1 + t5 * r2, s4 = t3 * r3 + t4 * r4 + t5 * r5, s5 = t3 * r6 + t4 * r7 + t5 * r8;
        double s6 = t6 * r0 + t7 * r1 + t8 * r2, s7 = t6 * r3 + t7 * r4 + t8 * r5, s8 = t6 * r6 + t7 * r7 + t8 * r8;
        // out = r s
        out[oi] = r0 * s0 + r1 * s3 + r2 * s6;
        out[oi + 1] = r0 * s1 + r1 * s4 + r2 * s7;
        out[oi + 2] = r0 * s2 + r1 * s5 + r2 * s8;
        out[oi + 3] = r3 * s0 + r4 * s3 + r5 * s6;
        out[oi + 4] = r3 * s1 + r4 * s4 + r5 * s7;
        out[oi + 5] = r3 * s2 + r4 * s5 + r5 * s8;
        out[oi + 6] = r6 * s0 + r7 * s3 + r8 * s6;
        out[oi + 7] = r6 * s1 + r7 * s4 + r8 * s7;
        out[oi + 8] = r6 * s2 + r7 * s5 + r8 * s8;
    }

    /** out = m^-1 by the adjugate; returns the determinant, and leaves out untouched when it is 0. */
    static double invert(double[] m, int mi, double[] out, int oi) {
        return invert(m[mi], m[mi + 1], m[mi + 2], m[mi + 3], m[mi + 4], m[mi + 5], m[mi + 6], m[mi + 7], m[mi + 8], out, oi);
    }

    /** {@link #invert(double[], int, double[], int)} of the matrix given by its rows (m00 m01 m02; ...). */
    static double invert(double m00, double m01, double m02, double m10, double m11, double m12, double m20, double m21, double m22,
            double[] out, int oi) {
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
