package handsim.cards.geom;

/**
 * Squared distances between the primitives of IPC (Li et al. 2020, sec. 4.3), with gradients and
 * Hessians. Every kernel takes the stacked vertex positions {@code x} (xyz interleaved, in the
 * order the method names) and writes the gradient ({@code 3n}) and the row-major Hessian
 * ({@code 3n x 3n}) when the arrays are not null; it returns the squared distance.
 *
 * <p>The point–line, point–plane and line–line distances are smooth functions of relative vectors:
 * point–line {@code |w|² − (a·w)²/|a|²} with {@code w = p − e0, a = e1 − e0}; point–plane and
 * line–line share {@code (v·(a×b))² / |a×b|²} (the triple-product form), with {@code v, a, b}
 * differences of the vertices. Derivatives are taken in those vectors and mapped back to the
 * vertices.
 */
public final class Distances {

    private Distances() {
    }

    // ---- point-point ---------------------------------------------------------------------------

    /** {@code |p0 − p1|²}, x = [p0, p1]. */
    public static double pointPoint(double[] x, double[] grad, double[] hess) {
        double dx = x[0] - x[3];
        double dy = x[1] - x[4];
        double dz = x[2] - x[5];
        if (grad != null) {
            grad[0] = 2 * dx;
            grad[1] = 2 * dy;
            grad[2] = 2 * dz;
            grad[3] = -2 * dx;
            grad[4] = -2 * dy;
            grad[5] = -2 * dz;
        }
        if (hess != null) {
            java.util.Arrays.fill(hess, 0, 36, 0.0);
            for (int i = 0; i < 3; i++) {
                hess[i * 6 + i] = 2;
                hess[(i + 3) * 6 + i + 3] = 2;
                hess[i * 6 + i + 3] = -2;
                hess[(i + 3) * 6 + i] = -2;
            }
        }
        return dx * dx + dy * dy + dz * dz;
    }

    // ---- point-line ----------------------------------------------------------------------------

    /** Distance from p to the infinite line through e0, e1; x = [p, e0, e1]. */
    public static double pointLine(double[] x, double[] grad, double[] hess) {
        double[] w = {x[0] - x[3], x[1] - x[4], x[2] - x[5]};
        double[] a = {x[6] - x[3], x[7] - x[4], x[8] - x[5]};
        double r = dot(a, w);
        double q = dot(a, a);
        double f = dot(w, w) - r * r / q;
        if (grad == null && hess == null) {
            return f;
        }
        // derivatives in y = (w, a)
        double[] gy = new double[6];
        for (int i = 0; i < 3; i++) {
            gy[i] = 2 * w[i] - 2 * r / q * a[i];
            gy[3 + i] = -2 * r / q * w[i] + 2 * r * r / (q * q) * a[i];
        }
        double[] hy = null;
        if (hess != null) {
            hy = new double[36];
            for (int i = 0; i < 3; i++) {
                for (int j = 0; j < 3; j++) {
                    double id = i == j ? 1 : 0;
                    double ww = 2 * id - 2 / q * a[i] * a[j];
                    double wa = -2 / q * a[i] * w[j] + 4 * r / (q * q) * a[i] * a[j] - 2 * r / q * id;
                    double aa = -2 / q * w[i] * w[j] + 4 * r / (q * q) * (w[i] * a[j] + a[i] * w[j])
                            - 8 * r * r / (q * q * q) * a[i] * a[j] + 2 * r * r / (q * q) * id;
                    hy[i * 6 + j] = ww;
                    hy[i * 6 + 3 + j] = wa;
                    hy[(3 + j) * 6 + i] = wa;
                    hy[(3 + i) * 6 + 3 + j] = aa;
                }
            }
        }
        // w = p - e0, a = e1 - e0
        mapBack(gy, hy, 2, new int[] {0, 2}, new int[] {1, 1}, 3, grad, hess);
        return f;
    }

    // ---- point-plane and line-line (triple-product form) ---------------------------------------

    /** Distance from p to the plane of t0, t1, t2; x = [p, t0, t1, t2]. */
    public static double pointPlane(double[] x, double[] grad, double[] hess) {
        double[] v = diff(x, 0, 1);
        double[] a = diff(x, 2, 1);
        double[] b = diff(x, 3, 1);
        return triple(v, a, b, new int[] {0, 2, 3}, new int[] {1, 1, 1}, grad, hess);
    }

    /** Distance between the infinite lines through ea0, ea1 and eb0, eb1; x = [ea0, ea1, eb0, eb1]. */
    public static double lineLine(double[] x, double[] grad, double[] hess) {
        double[] v = diff(x, 0, 2);
        double[] a = diff(x, 1, 0);
        double[] b = diff(x, 3, 2);
        return triple(v, a, b, new int[] {0, 1, 3}, new int[] {2, 0, 2}, grad, hess);
    }

    /** {@code s²/q} with {@code s = v·(a×b)}, {@code q = |a×b|²}; v, a, b = x[plus] − x[minus]. */
    private static double triple(double[] v, double[] a, double[] b, int[] plus, int[] minus,
                                 double[] grad, double[] hess) {
        double[] n = crossFma(a, b);
        double s = dot(v, n);
        double q = dot(n, n);
        double f = s * s / q;
        if (grad == null && hess == null) {
            return f;
        }
        // first derivatives of s and q in y = (v, a, b)
        double[] ds = new double[9];
        double[] dq = new double[9];
        double[] bxv = cross(b, v);
        double[] vxa = cross(v, a);
        double ab = dot(a, b);
        double aa = dot(a, a);
        double bb = dot(b, b);
        // dq/da = 2 b×n and dq/db = 2 n×a (free of the cancellation in |a|²|b|² − (a·b)²)
        double[] bxn = cross(b, n);
        double[] nxa = cross(n, a);
        for (int i = 0; i < 3; i++) {
            ds[i] = n[i];
            ds[3 + i] = bxv[i];
            ds[6 + i] = vxa[i];
            dq[3 + i] = 2 * bxn[i];
            dq[6 + i] = 2 * nxa[i];
        }
        double[] gy = new double[9];
        for (int i = 0; i < 9; i++) {
            gy[i] = 2 * s / q * ds[i] - s * s / (q * q) * dq[i];
        }
        double[] hy = null;
        if (hess != null) {
            // second derivatives: s is trilinear (cross-product matrices), q quartic in (a, b)
            double[] d2s = new double[81];
            double[] d2q = new double[81];
            putCrossBlock(d2s, 0, 1, b, -1);  // d(n)/da = -[b]x
            putCrossBlock(d2s, 0, 2, a, 1);   // d(n)/db = [a]x
            putCrossBlock(d2s, 1, 2, v, -1);  // d(b x v)/db = -[v]x
            for (int i = 0; i < 3; i++) {
                for (int j = 0; j < 3; j++) {
                    double id = i == j ? 1 : 0;
                    d2q[(3 + i) * 9 + 3 + j] = 2 * bb * id - 2 * b[i] * b[j];
                    d2q[(6 + i) * 9 + 6 + j] = 2 * aa * id - 2 * a[i] * a[j];
                    double abij = 4 * a[i] * b[j] - 2 * b[i] * a[j] - 2 * ab * id;
                    d2q[(3 + i) * 9 + 6 + j] = abij;
                    d2q[(6 + j) * 9 + 3 + i] = abij;
                }
            }
            hy = new double[81];
            double q2 = q * q;
            double q3 = q2 * q;
            for (int i = 0; i < 9; i++) {
                for (int j = 0; j < 9; j++) {
                    hy[i * 9 + j] = 2 / q * ds[i] * ds[j] + 2 * s / q * d2s[i * 9 + j]
                            - 2 * s / q2 * (ds[i] * dq[j] + dq[i] * ds[j])
                            + 2 * s * s / q3 * dq[i] * dq[j] - s * s / q2 * d2q[i * 9 + j];
                }
            }
        }
        mapBack(gy, hy, 3, plus, minus, 4, grad, hess);
        return f;
    }

    /** Writes {@code sign [c]x} into block (p, q) of a 9x9 matrix and its transpose into (q, p). */
    private static void putCrossBlock(double[] m, int p, int q, double[] c, double sign) {
        double[] k = {0, -c[2], c[1], c[2], 0, -c[0], -c[1], c[0], 0};
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                m[(3 * p + i) * 9 + 3 * q + j] = sign * k[i * 3 + j];
                m[(3 * q + j) * 9 + 3 * p + i] = sign * k[i * 3 + j];
            }
        }
    }

    /**
     * Maps derivatives in {@code m} relative vectors {@code y_k = x[plus_k] − x[minus_k]} to
     * derivatives in the {@code nv} vertices.
     */
    private static void mapBack(double[] gy, double[] hy, int m, int[] plus, int[] minus, int nv,
                                double[] grad, double[] hess) {
        int n = 3 * nv;
        if (grad != null) {
            java.util.Arrays.fill(grad, 0, n, 0.0);
            for (int k = 0; k < m; k++) {
                for (int c = 0; c < 3; c++) {
                    grad[3 * plus[k] + c] += gy[3 * k + c];
                    grad[3 * minus[k] + c] -= gy[3 * k + c];
                }
            }
        }
        if (hess != null) {
            java.util.Arrays.fill(hess, 0, n * n, 0.0);
            int my = 3 * m;
            for (int k = 0; k < m; k++) {
                for (int l = 0; l < m; l++) {
                    for (int c = 0; c < 3; c++) {
                        for (int d = 0; d < 3; d++) {
                            double h = hy[(3 * k + c) * my + 3 * l + d];
                            int pk = 3 * plus[k] + c;
                            int mk = 3 * minus[k] + c;
                            int pl = 3 * plus[l] + d;
                            int ml = 3 * minus[l] + d;
                            hess[pk * n + pl] += h;
                            hess[pk * n + ml] -= h;
                            hess[mk * n + pl] -= h;
                            hess[mk * n + ml] += h;
                        }
                    }
                }
            }
        }
    }

    // ---- segment/triangle distances with their closest-feature type ---------------------------

    /** Point–segment distance; x = [p, e0, e1]. Grad 9, Hessian 81. */
    public static double pointEdge(double[] x, double[] grad, double[] hess) {
        return evaluate(DistanceTypes.pointEdge(x), x, grad, hess, 3);
    }

    /** Point–triangle distance; x = [p, t0, t1, t2]. Grad 12, Hessian 144. */
    public static double pointTriangle(double[] x, double[] grad, double[] hess) {
        return evaluate(DistanceTypes.pointTriangle(x), x, grad, hess, 4);
    }

    /** Segment–segment distance; x = [ea0, ea1, eb0, eb1]. Grad 12, Hessian 144. */
    public static double edgeEdge(double[] x, double[] grad, double[] hess) {
        return evaluate(DistanceTypes.edgeEdge(x), x, grad, hess, 4);
    }

    /**
     * The squared distance of the closest-feature pair {@code type} (from {@link DistanceTypes}),
     * its derivatives scattered into the full stencil of {@code nv} vertices.
     */
    public static double evaluate(DistanceType type, double[] x, double[] grad, double[] hess, int nv) {
        int[] idx = type.vertices();
        int k = idx.length;
        if (k == nv && type.kernel() != Kernel.POINT_POINT && type.kernel() != Kernel.POINT_LINE) {
            return type.kernel() == Kernel.POINT_PLANE ? pointPlane(x, grad, hess) : lineLine(x, grad, hess);
        }
        double[] sub = new double[3 * k];
        for (int i = 0; i < k; i++) {
            System.arraycopy(x, 3 * idx[i], sub, 3 * i, 3);
        }
        double[] g = grad == null ? null : new double[3 * k];
        double[] h = hess == null ? null : new double[9 * k * k];
        double d = kernel(type.kernel(), sub, g, h);
        int n = 3 * nv;
        if (grad != null) {
            java.util.Arrays.fill(grad, 0, n, 0.0);
            for (int i = 0; i < k; i++) {
                for (int c = 0; c < 3; c++) {
                    grad[3 * idx[i] + c] = g[3 * i + c];
                }
            }
        }
        if (hess != null) {
            java.util.Arrays.fill(hess, 0, n * n, 0.0);
            int m = 3 * k;
            for (int i = 0; i < m; i++) {
                int gi = 3 * idx[i / 3] + i % 3;
                for (int j = 0; j < m; j++) {
                    int gj = 3 * idx[j / 3] + j % 3;
                    hess[gi * n + gj] = h[i * m + j];
                }
            }
        }
        return d;
    }

    /** One of the four smooth kernels on its own vertices ({@code sub} holds 2, 3 or 4 of them). */
    public static double kernel(Kernel kernel, double[] sub, double[] grad, double[] hess) {
        switch (kernel) {
            case POINT_POINT:
                return pointPoint(sub, grad, hess);
            case POINT_LINE:
                return pointLine(sub, grad, hess);
            case POINT_PLANE:
                return pointPlane(sub, grad, hess);
            default:
                return lineLine(sub, grad, hess);
        }
    }

    /** The smooth distance functions the closest-feature types reduce to. */
    public enum Kernel {
        POINT_POINT(2), POINT_LINE(3), POINT_PLANE(4), LINE_LINE(4);

        private final int vertices;

        Kernel(int vertices) {
            this.vertices = vertices;
        }

        public int vertexCount() {
            return vertices;
        }
    }

    // ---- small vector helpers -------------------------------------------------------------------

    static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    /** a × b with a fused multiply-add per component (the rounding of the reference's build). */
    static double[] crossFma(double[] a, double[] b) {
        return new double[] {
            Math.fma(a[1], b[2], -(a[2] * b[1])),
            Math.fma(a[2], b[0], -(a[0] * b[2])),
            Math.fma(a[0], b[1], -(a[1] * b[0])),
        };
    }

    /** {@code x[vertex i] − x[vertex j]}. */
    static double[] diff(double[] x, int i, int j) {
        return new double[] {x[3 * i] - x[3 * j], x[3 * i + 1] - x[3 * j + 1], x[3 * i + 2] - x[3 * j + 2]};
    }
}
