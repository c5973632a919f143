package handsim.cards.energy;

import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.cards.linalg.SymmetricEigen;

/**
 * Central-difference checks of an {@link Energy}: the gradient against differences of the value,
 * the exact Hessian against differences of the gradient, and the projected Hessian for
 * semi-definiteness. Central differences with step h err by O(h²) (third derivatives times h²/6),
 * so a relative tolerance of 1e-5 at h = 1e-7 of the coordinate scale leaves room for rounding
 * (ε/h ≈ 1e-9 relative to the value).
 */
public final class FiniteDifference {

    private FiniteDifference() {
    }

    /** Dense sink for tests. */
    public static final class Dense implements HessianSink {
        public final int n;
        public final double[] m;

        public Dense(int nodes) {
            this.n = 3 * nodes;
            this.m = new double[n * n];
        }

        @Override
        public void add(int[] nodes, int k, double[] h) {
            for (int a = 0; a < k; a++) {
                for (int b = 0; b < k; b++) {
                    for (int r = 0; r < 3; r++) {
                        for (int c = 0; c < 3; c++) {
                            m[(3 * nodes[a] + r) * n + 3 * nodes[b] + c] += h[(3 * a + r) * 3 * k + 3 * b + c];
                        }
                    }
                }
            }
        }
    }

    public static void check(Energy e, double[] x, double step, double tol) {
        int n = x.length;
        double[] g = new double[n];
        e.addGradient(x, g);
        double gScale = 0;
        for (double v : g) {
            gScale = Math.max(gScale, Math.abs(v));
        }
        double[] xp = x.clone();
        for (int i = 0; i < n; i++) {
            xp[i] = x[i] + step;
            double ep = e.value(xp);
            xp[i] = x[i] - step;
            double em = e.value(xp);
            xp[i] = x[i];
            double fd = (ep - em) / (2 * step);
            assertTrue(Math.abs(fd - g[i]) <= tol * gScale, "gradient[" + i + "]: analytic " + g[i] + ", central difference " + fd);
        }
        Dense exact = new Dense(n / 3);
        e.addHessian(x, exact, false);
        double hScale = 0;
        for (double v : exact.m) {
            hScale = Math.max(hScale, Math.abs(v));
        }
        double[] gp = new double[n];
        double[] gm = new double[n];
        for (int j = 0; j < n; j++) {
            java.util.Arrays.fill(gp, 0);
            java.util.Arrays.fill(gm, 0);
            xp[j] = x[j] + step;
            e.addGradient(xp, gp);
            xp[j] = x[j] - step;
            e.addGradient(xp, gm);
            xp[j] = x[j];
            for (int i = 0; i < n; i++) {
                double fd = (gp[i] - gm[i]) / (2 * step);
                assertTrue(Math.abs(fd - exact.m[i * n + j]) <= tol * hScale,
                        "hessian[" + i + "][" + j + "]: analytic " + exact.m[i * n + j] + ", central difference " + fd);
            }
        }
        Dense projected = new Dense(n / 3);
        e.addHessian(x, projected, true);
        if (n <= 12) {
            SymmetricEigen eig = new SymmetricEigen(n);
            eig.decompose(projected.m, n);
            for (int i = 0; i < n; i++) {
                assertTrue(eig.value(i) >= -1e-9 * hScale, "projected Hessian eigenvalue " + eig.value(i));
            }
        }
    }
}
