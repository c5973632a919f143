package handsim.cards.linalg;

import java.util.Arrays;

/**
 * Preconditioned conjugate gradients for H x = b from x = 0 (Saad 2003, Alg. 9.1), with H and
 * the preconditioner given as linear maps and every vector allocated once for one size.
 */
final class ConjugateGradients {

    /** y = A x, overwriting y. */
    @FunctionalInterface
    interface LinearMap {
        void apply(double[] x, double[] y);
    }

    private final int n;
    private final LinearMap h;
    private final LinearMap preconditioner;
    private final double[] x;
    private final double[] r;
    private final double[] z;
    private final double[] p;
    private final double[] q;

    ConjugateGradients(int n, LinearMap h, LinearMap preconditioner) {
        this.n = n;
        this.h = h;
        this.preconditioner = preconditioner;
        x = new double[n];
        r = new double[n];
        z = new double[n];
        p = new double[n];
        q = new double[n];
    }

    /**
     * Solves H x = b until the preconditioned residual rᵀz falls below {@code tolerance}² times
     * its start; the iterations it took, or 0 if it did not converge within {@code maxIterations}
     * (or H showed a direction of non-positive curvature). The solution is {@link #solution()}.
     */
    int solve(double[] b, double tolerance, int maxIterations) {
        Arrays.fill(x, 0);
        System.arraycopy(b, 0, r, 0, n);
        preconditioner.apply(r, z);
        System.arraycopy(z, 0, p, 0, n);
        double rz = dot(r, z);
        double target = tolerance * tolerance * rz;
        if (rz == 0) {
            return 1;
        }
        for (int k = 1; k <= maxIterations; k++) {
            h.apply(p, q);
            double pq = dot(p, q);
            if (!(pq > 0)) {
                return 0;
            }
            double a = rz / pq;
            for (int i = 0; i < n; i++) {
                x[i] += a * p[i];
                r[i] -= a * q[i];
            }
            preconditioner.apply(r, z);
            double rzNext = dot(r, z);
            if (rzNext <= target) {
                return k;
            }
            double beta = rzNext / rz;
            for (int i = 0; i < n; i++) {
                p[i] = z[i] + beta * p[i];
            }
            rz = rzNext;
        }
        return 0;
    }

    /** The last solve's x (live: the next solve overwrites it). */
    double[] solution() {
        return x;
    }

    private static double dot(double[] a, double[] b) {
        double s = 0;
        for (int i = 0; i < a.length; i++) {
            s += a[i] * b[i];
        }
        return s;
    }
}
