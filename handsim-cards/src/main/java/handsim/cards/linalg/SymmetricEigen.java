package handsim.cards.linalg;

/**
 * Eigen-decomposition of small dense symmetric matrices (n ≤ 12): Householder reduction to
 * tridiagonal form and the implicit QL algorithm (tred2/tql2, as in EISPACK and JAMA), and the
 * projection of an element Hessian onto the positive semi-definite cone (negative eigenvalues set
 * to zero) that projected Newton needs (Teran et al. 2005). One instance holds the workspace for
 * matrices up to its size; it is not thread-safe.
 */
public final class SymmetricEigen {

    private final int capacity;
    /** eigenvectors, row-major n x n: column e is eigenvector e */
    private final double[] v;
    private final double[] d;
    private final double[] e;
    private int n;

    public SymmetricEigen(int capacity) {
        this.capacity = capacity;
        this.v = new double[capacity * capacity];
        this.d = new double[capacity];
        this.e = new double[capacity];
    }

    /**
     * Decomposes the row-major symmetric {@code n x n} matrix {@code m} (its upper triangle is
     * read as the symmetric part); afterwards {@link #value(int)} and {@link #vector(int, int)}
     * hold the eigenpairs.
     */
    public void decompose(double[] m, int size) {
        if (size > capacity) {
            throw new IllegalArgumentException("matrix of size " + size + " exceeds capacity " + capacity);
        }
        n = size;
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                v[i * n + j] = 0.5 * (m[i * n + j] + m[j * n + i]);
            }
        }
        tred2();
        tql2();
    }

    public double value(int i) {
        return d[i];
    }

    /** Component {@code k} of eigenvector {@code i}. */
    public double vector(int i, int k) {
        return v[k * n + i];
    }

    /**
     * Replaces the symmetric {@code n x n} matrix {@code m} by its projection onto the positive
     * semi-definite cone: V max(Λ, 0) Vᵀ. A matrix already semi-definite is left untouched.
     */
    public void projectToPsd(double[] m, int size) {
        if (positiveDefinite(m, size)) {
            return; // a Cholesky factorisation exists: every eigenvalue is positive
        }
        decompose(m, size);
        boolean negative = false;
        for (int i = 0; i < n; i++) {
            if (d[i] < 0) {
                negative = true;
                break;
            }
        }
        if (!negative) {
            return;
        }
        java.util.Arrays.fill(m, 0, n * n, 0.0);
        for (int k = 0; k < n; k++) {
            double lam = d[k];
            if (lam <= 0) {
                continue;
            }
            for (int i = 0; i < n; i++) {
                double vi = lam * v[i * n + k];
                if (vi == 0) {
                    continue;
                }
                for (int j = i; j < n; j++) {
                    m[i * n + j] += vi * v[j * n + k];
                }
            }
        }
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < i; j++) {
                m[i * n + j] = m[j * n + i];
            }
        }
    }

    /**
     * Whether the symmetric {@code size x size} matrix {@code m} has a Cholesky factorisation with
     * positive pivots (about n³/6 operations against the eigen-decomposition's tens of n³), in
     * the workspace; {@code m} is not changed.
     */
    private boolean positiveDefinite(double[] m, int size) {
        if (size > capacity) {
            throw new IllegalArgumentException("matrix of size " + size + " exceeds capacity " + capacity);
        }
        double[] l = v;
        for (int j = 0; j < size; j++) {
            double diag = m[j * size + j];
            for (int k = 0; k < j; k++) {
                diag -= l[j * size + k] * l[j * size + k];
            }
            if (!(diag > 0)) {
                return false;
            }
            double root = Math.sqrt(diag);
            l[j * size + j] = root;
            for (int i = j + 1; i < size; i++) {
                double sum = 0.5 * (m[i * size + j] + m[j * size + i]);
                for (int k = 0; k < j; k++) {
                    sum -= l[i * size + k] * l[j * size + k];
                }
                l[i * size + j] = sum / root;
            }
        }
        return true;
    }

    /** Householder tridiagonalisation; v becomes the accumulated transform, d/e the tridiagonal. */
    private void tred2() {
        for (int j = 0; j < n; j++) {
            d[j] = v[(n - 1) * n + j];
        }
        for (int i = n - 1; i > 0; i--) {
            double scale = 0.0;
            double h = 0.0;
            for (int k = 0; k < i; k++) {
                scale += Math.abs(d[k]);
            }
            if (scale == 0.0) {
                e[i] = d[i - 1];
                for (int j = 0; j < i; j++) {
                    d[j] = v[(i - 1) * n + j];
                    v[i * n + j] = 0.0;
                    v[j * n + i] = 0.0;
                }
            } else {
                for (int k = 0; k < i; k++) {
                    d[k] /= scale;
                    h += d[k] * d[k];
                }
                double f = d[i - 1];
                double g = Math.sqrt(h);
                if (f > 0) {
                    g = -g;
                }
                e[i] = scale * g;
                h = h - f * g;
                d[i - 1] = f - g;
                for (int j = 0; j < i; j++) {
                    e[j] = 0.0;
                }
                for (int j = 0; j < i; j++) {
                    f = d[j];
                    v[j * n + i] = f;
                    g = e[j] + v[j * n + j] * f;
                    for (int k = j + 1; k <= i - 1; k++) {
                        g += v[k * n + j] * d[k];
                        e[k] += v[k * n + j] * f;
                    }
                    e[j] = g;
                }
                f = 0.0;
                for (int j = 0; j < i; j++) {
                    e[j] /= h;
                    f += e[j] * d[j];
                }
                double hh = f / (h + h);
                for (int j = 0; j < i; j++) {
                    e[j] -= hh * d[j];
                }
                for (int j = 0; j < i; j++) {
                    f = d[j];
                    g = e[j];
                    for (int k = j; k <= i - 1; k++) {
                        v[k * n + j] -= f * e[k] + g * d[k];
                    }
                    d[j] = v[(i - 1) * n + j];
                    v[i * n + j] = 0.0;
                }
            }
            d[i] = h;
        }
        for (int i = 0; i < n - 1; i++) {
            v[(n - 1) * n + i] = v[i * n + i];
            v[i * n + i] = 1.0;
            double h = d[i + 1];
            if (h != 0.0) {
                for (int k = 0; k <= i; k++) {
                    d[k] = v[k * n + i + 1] / h;
                }
                for (int j = 0; j <= i; j++) {
                    double g = 0.0;
                    for (int k = 0; k <= i; k++) {
                        g += v[k * n + i + 1] * v[k * n + j];
                    }
                    for (int k = 0; k <= i; k++) {
                        v[k * n + j] -= g * d[k];
                    }
                }
            }
            for (int k = 0; k <= i; k++) {
                v[k * n + i + 1] = 0.0;
            }
        }
        for (int j = 0; j < n; j++) {
            d[j] = v[(n - 1) * n + j];
            v[(n - 1) * n + j] = 0.0;
        }
        v[(n - 1) * n + n - 1] = 1.0;
        e[0] = 0.0;
    }

    /** Implicit QL on the tridiagonal (d, e), accumulating the rotations into v. */
    private void tql2() {
        for (int i = 1; i < n; i++) {
            e[i - 1] = e[i];
        }
        e[n - 1] = 0.0;
        double f = 0.0;
        double tst1 = 0.0;
        double eps = Math.ulp(1.0);
        for (int l = 0; l < n; l++) {
            tst1 = Math.max(tst1, Math.abs(d[l]) + Math.abs(e[l]));
            int m = l;
            while (m < n) {
                if (Math.abs(e[m]) <= eps * tst1) {
                    break;
                }
                m++;
            }
            if (m == n) {
                m = n - 1;
            }
            if (m > l) {
                for (int iter = 0; iter < 60; iter++) {
                    double g = d[l];
                    double p = (d[l + 1] - g) / (2.0 * e[l]);
                    double r = Math.hypot(p, 1.0);
                    if (p < 0) {
                        r = -r;
                    }
                    d[l] = e[l] / (p + r);
                    d[l + 1] = e[l] * (p + r);
                    double dl1 = d[l + 1];
                    double h = g - d[l];
                    for (int i = l + 2; i < n; i++) {
                        d[i] -= h;
                    }
                    f = f + h;
                    p = d[m];
                    double c = 1.0;
                    double c2 = c;
                    double c3 = c;
                    double el1 = e[l + 1];
                    double s = 0.0;
                    double s2 = 0.0;
                    for (int i = m - 1; i >= l; i--) {
                        c3 = c2;
                        c2 = c;
                        s2 = s;
                        g = c * e[i];
                        h = c * p;
                        r = Math.hypot(p, e[i]);
                        e[i + 1] = s * r;
                        s = e[i] / r;
                        c = p / r;
                        p = c * d[i] - s * g;
                        d[i + 1] = h + s * (c * g + s * d[i]);
                        for (int k = 0; k < n; k++) {
                            h = v[k * n + i + 1];
                            v[k * n + i + 1] = s * v[k * n + i] + c * h;
                            v[k * n + i] = c * v[k * n + i] - s * h;
                        }
                    }
                    p = -s * s2 * c3 * el1 * e[l] / dl1;
                    e[l] = s * p;
                    d[l] = c * p;
                    if (Math.abs(e[l]) <= eps * tst1) {
                        break;
                    }
                }
            }
            d[l] = d[l] + f;
            e[l] = 0.0;
        }
    }
}
