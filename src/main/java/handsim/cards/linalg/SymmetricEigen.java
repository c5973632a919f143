package handsim.cards.linalg;

/**
 * Eigen-decomposition of small dense symmetric matrices (n ≤ 12) by cyclic Jacobi rotations, and
 * the projection of an element Hessian onto the positive semi-definite cone (negative eigenvalues
 * set to zero) that projected Newton needs (Teran et al. 2005). One instance holds the workspace
 * for matrices up to its size; it is not thread-safe.
 */
public final class SymmetricEigen {

    private static final int MAX_SWEEPS = 50;

    private final int capacity;
    private final double[] a;
    private final double[] vectors;
    private final double[] values;

    public SymmetricEigen(int capacity) {
        this.capacity = capacity;
        this.a = new double[capacity * capacity];
        this.vectors = new double[capacity * capacity];
        this.values = new double[capacity];
    }

    /**
     * Decomposes the row-major symmetric {@code n x n} matrix {@code m}; afterwards {@link
     * #value(int)} and {@link #vector(int, int)} hold the eigenpairs.
     */
    public void decompose(double[] m, int n) {
        if (n > capacity) {
            throw new IllegalArgumentException("matrix of size " + n + " exceeds capacity " + capacity);
        }
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                a[i * n + j] = 0.5 * (m[i * n + j] + m[j * n + i]);
                vectors[i * n + j] = i == j ? 1 : 0;
            }
        }
        double scale = 0;
        for (int i = 0; i < n * n; i++) {
            scale = Math.max(scale, Math.abs(a[i]));
        }
        double tiny = scale * 1e-300 + Double.MIN_NORMAL;
        for (int sweep = 0; sweep < MAX_SWEEPS; sweep++) {
            double off = 0;
            for (int p = 0; p < n; p++) {
                for (int q = p + 1; q < n; q++) {
                    off += a[p * n + q] * a[p * n + q];
                }
            }
            if (off <= 1e-26 * scale * scale || off < tiny) {
                break;
            }
            for (int p = 0; p < n; p++) {
                for (int q = p + 1; q < n; q++) {
                    double apq = a[p * n + q];
                    if (Math.abs(apq) < tiny || Math.abs(apq) < 1e-14 * scale) {
                        continue;
                    }
                    double app = a[p * n + p];
                    double aqq = a[q * n + q];
                    double theta = (aqq - app) / (2 * apq);
                    double t = Math.signum(theta) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
                    if (theta == 0) {
                        t = 1;
                    }
                    double c = 1 / Math.sqrt(t * t + 1);
                    double s = t * c;
                    for (int k = 0; k < n; k++) {
                        double akp = a[k * n + p];
                        double akq = a[k * n + q];
                        a[k * n + p] = c * akp - s * akq;
                        a[k * n + q] = s * akp + c * akq;
                    }
                    for (int k = 0; k < n; k++) {
                        double apk = a[p * n + k];
                        double aqk = a[q * n + k];
                        a[p * n + k] = c * apk - s * aqk;
                        a[q * n + k] = s * apk + c * aqk;
                    }
                    for (int k = 0; k < n; k++) {
                        double vkp = vectors[k * n + p];
                        double vkq = vectors[k * n + q];
                        vectors[k * n + p] = c * vkp - s * vkq;
                        vectors[k * n + q] = s * vkp + c * vkq;
                    }
                }
            }
        }
        for (int i = 0; i < n; i++) {
            values[i] = a[i * n + i];
        }
        size = n;
    }

    private int size;

    public double value(int i) {
        return values[i];
    }

    /** Component {@code k} of eigenvector {@code i}. */
    public double vector(int i, int k) {
        return vectors[k * size + i];
    }

    /**
     * Replaces the symmetric {@code n x n} matrix {@code m} by its projection onto the positive
     * semi-definite cone: V max(Λ, 0) Vᵀ. A matrix already semi-definite is left untouched.
     */
    public void projectToPsd(double[] m, int n) {
        decompose(m, n);
        boolean negative = false;
        for (int i = 0; i < n; i++) {
            if (values[i] < 0) {
                negative = true;
                break;
            }
        }
        if (!negative) {
            return;
        }
        java.util.Arrays.fill(m, 0, n * n, 0.0);
        for (int e = 0; e < n; e++) {
            double lam = values[e];
            if (lam <= 0) {
                continue;
            }
            for (int i = 0; i < n; i++) {
                double vi = lam * vectors[i * n + e];
                if (vi == 0) {
                    continue;
                }
                for (int j = 0; j < n; j++) {
                    m[i * n + j] += vi * vectors[j * n + e];
                }
            }
        }
    }
}
