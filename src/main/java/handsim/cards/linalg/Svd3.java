package handsim.cards.linalg;

/**
 * The rotation-variant singular value decomposition F = U Σ Vᵀ of a 3x3 matrix (Irving et al.
 * 2004): U and V are rotations, σ1 ≥ σ2 ≥ |σ3|, and σ3 carries the sign of det F, so an inverted
 * element has a negative σ3. V comes from the Jacobi eigenvectors of FᵀF, U from Gram–Schmidt on
 * F V (robust when singular values coincide or vanish). Not thread-safe: reuse one per thread.
 */
public final class Svd3 {

    /** Row-major U and V, and the singular values. */
    public final double[] u = new double[9];
    public final double[] v = new double[9];
    public final double[] sigma = new double[3];

    private final SymmetricEigen eigen = new SymmetricEigen(3);
    private final double[] ftf = new double[9];

    /** Decomposes the row-major {@code f}. */
    public void decompose(double[] f) {
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                ftf[i * 3 + j] = f[i] * f[j] + f[3 + i] * f[3 + j] + f[6 + i] * f[6 + j];
            }
        }
        eigen.decompose(ftf, 3);
        // order eigenpairs by decreasing eigenvalue
        int[] order = {0, 1, 2};
        for (int i = 0; i < 3; i++) {
            for (int j = i + 1; j < 3; j++) {
                if (eigen.value(order[j]) > eigen.value(order[i])) {
                    int t = order[i];
                    order[i] = order[j];
                    order[j] = t;
                }
            }
        }
        for (int c = 0; c < 3; c++) {
            for (int r = 0; r < 3; r++) {
                v[r * 3 + c] = eigen.vector(order[c], r);
            }
        }
        // make V a rotation
        if (det(v) < 0) {
            for (int r = 0; r < 3; r++) {
                v[r * 3 + 2] = -v[r * 3 + 2];
            }
        }
        // B = F V; U by Gram-Schmidt on B's columns, the third as u1 × u2
        double[] b = new double[9];
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                b[r * 3 + c] = f[r * 3] * v[c] + f[r * 3 + 1] * v[3 + c] + f[r * 3 + 2] * v[6 + c];
            }
        }
        double[] u1 = {b[0], b[3], b[6]};
        double s1 = norm(u1);
        if (s1 < 1e-300) {
            u1 = new double[] {1, 0, 0};
        } else {
            scale(u1, 1 / s1);
        }
        double[] b2 = {b[1], b[4], b[7]};
        double p = dot(u1, b2);
        double[] u2 = {b2[0] - p * u1[0], b2[1] - p * u1[1], b2[2] - p * u1[2]};
        double s2 = norm(u2);
        if (s2 < 1e-300 * Math.max(1, s1)) {
            u2 = anyPerpendicular(u1);
        } else {
            scale(u2, 1 / s2);
        }
        double[] u3 = cross(u1, u2);
        double[] b3 = {b[2], b[5], b[8]};
        sigma[0] = s1;
        sigma[1] = dot(u2, b2);
        sigma[2] = dot(u3, b3);
        for (int r = 0; r < 3; r++) {
            u[r * 3] = u1[r];
            u[r * 3 + 1] = u2[r];
            u[r * 3 + 2] = u3[r];
        }
    }

    private static double[] anyPerpendicular(double[] a) {
        double[] t = Math.abs(a[0]) < 0.9 ? new double[] {1, 0, 0} : new double[] {0, 1, 0};
        double[] c = cross(a, t);
        scale(c, 1 / norm(c));
        return c;
    }

    static double det(double[] m) {
        return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6])
                + m[2] * (m[3] * m[7] - m[4] * m[6]);
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double norm(double[] a) {
        return Math.sqrt(dot(a, a));
    }

    private static void scale(double[] a, double s) {
        a[0] *= s;
        a[1] *= s;
        a[2] *= s;
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
}
