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

    private final double[] ftf = new double[9];
    private final double[] values = new double[3];

    /**
     * Cyclic Jacobi on a symmetric 3x3 matrix {@code a} (destroyed): eigenvectors as the columns
     * of {@code vec} (row-major), eigenvalues in {@code val}. Stops when the off-diagonal part is
     * below 1e-15 of the matrix's scale.
     */
    static void jacobi3(double[] a, double[] vec, double[] val) {
        double a00 = a[0];
        double a01 = a[1];
        double a02 = a[2];
        double a11 = a[4];
        double a12 = a[5];
        double a22 = a[8];
        java.util.Arrays.fill(vec, 0);
        vec[0] = 1;
        vec[4] = 1;
        vec[8] = 1;
        double scale = Math.abs(a00) + Math.abs(a11) + Math.abs(a22) + Math.abs(a01) + Math.abs(a02) + Math.abs(a12);
        double tol = 1e-15 * scale;
        for (int sweep = 0; sweep < 20; sweep++) {
            if (Math.abs(a01) <= tol && Math.abs(a02) <= tol && Math.abs(a12) <= tol) {
                break;
            }
            for (int pair = 0; pair < 3; pair++) {
                int p = pair == 2 ? 1 : 0;
                int q = pair == 0 ? 1 : 2;
                double apq = pair == 0 ? a01 : pair == 1 ? a02 : a12;
                if (Math.abs(apq) <= tol * 1e-3) {
                    continue;
                }
                double app = p == 0 ? a00 : a11;
                double aqq = q == 1 ? a11 : a22;
                double theta = (aqq - app) / (2 * apq);
                double t = theta == 0 ? 1 : Math.signum(theta) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
                double c = 1 / Math.sqrt(t * t + 1);
                double sn = t * c;
                // rotate rows/columns p, q of the symmetric matrix
                int r = 3 - p - q;
                double arp = r == 0 ? (p == 1 ? a01 : a02) : r == 1 ? (p == 0 ? a01 : a12) : (p == 0 ? a02 : a12);
                double arq = r == 0 ? (q == 1 ? a01 : a02) : r == 1 ? (q == 0 ? a01 : a12) : (q == 0 ? a02 : a12);
                double nrp = c * arp - sn * arq;
                double nrq = sn * arp + c * arq;
                double npp = app - t * apq;
                double nqq = aqq + t * apq;
                if (p == 0) {
                    a00 = npp;
                } else {
                    a11 = npp;
                }
                if (q == 1) {
                    a11 = nqq;
                } else {
                    a22 = nqq;
                }
                if (pair == 0) {
                    a01 = 0;
                    a02 = nrp;
                    a12 = nrq;
                } else if (pair == 1) {
                    a02 = 0;
                    a01 = nrp;
                    a12 = nrq;
                } else {
                    a12 = 0;
                    a01 = nrp;
                    a02 = nrq;
                }
                for (int k = 0; k < 3; k++) {
                    double vkp = vec[k * 3 + p];
                    double vkq = vec[k * 3 + q];
                    vec[k * 3 + p] = c * vkp - sn * vkq;
                    vec[k * 3 + q] = sn * vkp + c * vkq;
                }
            }
        }
        val[0] = a00;
        val[1] = a11;
        val[2] = a22;
    }

    /** Decomposes the row-major {@code f}. */
    public void decompose(double[] f) {
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                ftf[i * 3 + j] = f[i] * f[j] + f[3 + i] * f[3 + j] + f[6 + i] * f[6 + j];
            }
        }
        jacobi3(ftf, v, values);
        // order eigenpairs by decreasing eigenvalue
        for (int i = 0; i < 3; i++) {
            for (int j = i + 1; j < 3; j++) {
                if (values[j] > values[i]) {
                    double t = values[i];
                    values[i] = values[j];
                    values[j] = t;
                    for (int r = 0; r < 3; r++) {
                        t = v[r * 3 + i];
                        v[r * 3 + i] = v[r * 3 + j];
                        v[r * 3 + j] = t;
                    }
                }
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

    /**
     * The signed singular values of F (σ1 ≥ σ2 ≥ |σ3|, σ3 with the sign of det F) in closed form,
     * from the eigenvalues of FᵀF by the trigonometric solution of its characteristic cubic.
     */
    public static void singularValues(double[] f, double[] out) {
        double a00 = f[0] * f[0] + f[3] * f[3] + f[6] * f[6];
        double a11 = f[1] * f[1] + f[4] * f[4] + f[7] * f[7];
        double a22 = f[2] * f[2] + f[5] * f[5] + f[8] * f[8];
        double a01 = f[0] * f[1] + f[3] * f[4] + f[6] * f[7];
        double a02 = f[0] * f[2] + f[3] * f[5] + f[6] * f[8];
        double a12 = f[1] * f[2] + f[4] * f[5] + f[7] * f[8];
        double p1 = a01 * a01 + a02 * a02 + a12 * a12;
        double q = (a00 + a11 + a22) / 3;
        double d0 = a00 - q;
        double d1 = a11 - q;
        double d2 = a22 - q;
        double p2 = d0 * d0 + d1 * d1 + d2 * d2 + 2 * p1;
        double e1;
        double e2;
        double e3;
        if (p2 <= 1e-300) {
            e1 = q;
            e2 = q;
            e3 = q;
        } else {
            double p = Math.sqrt(p2 / 6);
            // det((A − qI)/p) / 2
            double r = (d0 * (d1 * d2 - a12 * a12) - a01 * (a01 * d2 - a12 * a02) + a02 * (a01 * a12 - d1 * a02)) / (2 * p * p * p);
            double phi = Math.acos(Math.max(-1, Math.min(1, r))) / 3;
            e1 = q + 2 * p * Math.cos(phi);
            e3 = q + 2 * p * Math.cos(phi + 2 * Math.PI / 3);
            e2 = 3 * q - e1 - e3;
        }
        out[0] = Math.sqrt(Math.max(e1, 0));
        out[1] = Math.sqrt(Math.max(e2, 0));
        out[2] = Math.sqrt(Math.max(e3, 0));
        if (det(f) < 0) {
            out[2] = -out[2];
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
