package handsim.math;

/** Small dense linear algebra on row-major {@code double[]} matrices, allocation-free. */
public final class Dense {

    private Dense() {
    }

    /**
     * Solves {@code A x = b} for symmetric positive definite {@code A} (n x n, row-major) by
     * Cholesky factorisation. {@code A} is overwritten by its factor, {@code b} by {@code x}.
     *
     * @throws ArithmeticException if {@code A} is not positive definite
     */
    public static void solveSpd(double[] a, double[] b, int n) {
        for (int j = 0; j < n; j++) {
            double d = a[j * n + j];
            for (int k = 0; k < j; k++) {
                d -= a[j * n + k] * a[j * n + k];
            }
            if (!(d > 0)) {
                throw new ArithmeticException("matrix is not positive definite (pivot " + j + " = " + d + ")");
            }
            double l = Math.sqrt(d);
            a[j * n + j] = l;
            for (int i = j + 1; i < n; i++) {
                double s = a[i * n + j];
                for (int k = 0; k < j; k++) {
                    s -= a[i * n + k] * a[j * n + k];
                }
                a[i * n + j] = s / l;
            }
        }
        // forward: L y = b
        for (int i = 0; i < n; i++) {
            double s = b[i];
            for (int k = 0; k < i; k++) {
                s -= a[i * n + k] * b[k];
            }
            b[i] = s / a[i * n + i];
        }
        // backward: L^T x = y
        for (int i = n - 1; i >= 0; i--) {
            double s = b[i];
            for (int k = i + 1; k < n; k++) {
                s -= a[k * n + i] * b[k];
            }
            b[i] = s / a[i * n + i];
        }
    }
}
