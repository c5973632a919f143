package handsim.cards.geom;

/**
 * A value with its gradient and Hessian in {@code n} variables: forward-mode second-order
 * automatic differentiation for the shell energies (membrane, hinge bending), whose Hessians
 * would otherwise be long hand-derived formulas. Jets are mutable and reused (each operation
 * writes into {@code this}), so element loops allocate nothing. The Hessian is stored packed
 * (upper triangle, row by row).
 */
public final class Jet {

    public final int n;
    public double v;
    public final double[] g;
    /** Packed upper triangle: entry (i, j), i <= j, at {@code i*n - i*(i-1)/2 + (j - i)}. */
    public final double[] h;

    public Jet(int n) {
        this.n = n;
        this.g = new double[n];
        this.h = new double[n * (n + 1) / 2];
    }

    /** The {@code i}-th variable with value {@code value}. */
    public Jet variable(int i, double value) {
        constant(value);
        g[i] = 1;
        return this;
    }

    public Jet constant(double value) {
        v = value;
        java.util.Arrays.fill(g, 0);
        java.util.Arrays.fill(h, 0);
        return this;
    }

    public Jet set(Jet a) {
        v = a.v;
        System.arraycopy(a.g, 0, g, 0, n);
        System.arraycopy(a.h, 0, h, 0, h.length);
        return this;
    }

    /** this = a + b. */
    public Jet add(Jet a, Jet b) {
        v = a.v + b.v;
        for (int i = 0; i < n; i++) {
            g[i] = a.g[i] + b.g[i];
        }
        for (int k = 0; k < h.length; k++) {
            h[k] = a.h[k] + b.h[k];
        }
        return this;
    }

    /** this = a − b. */
    public Jet sub(Jet a, Jet b) {
        v = a.v - b.v;
        for (int i = 0; i < n; i++) {
            g[i] = a.g[i] - b.g[i];
        }
        for (int k = 0; k < h.length; k++) {
            h[k] = a.h[k] - b.h[k];
        }
        return this;
    }

    /** this = s a (a may be this). */
    public Jet scale(Jet a, double s) {
        v = a.v * s;
        for (int i = 0; i < n; i++) {
            g[i] = a.g[i] * s;
        }
        for (int k = 0; k < h.length; k++) {
            h[k] = a.h[k] * s;
        }
        return this;
    }

    /** this = α a + β b + γ (this may be a or b). */
    public Jet linear(double alpha, Jet a, double beta, Jet b, double gamma) {
        v = alpha * a.v + beta * b.v + gamma;
        for (int i = 0; i < n; i++) {
            g[i] = alpha * a.g[i] + beta * b.g[i];
        }
        for (int k = 0; k < h.length; k++) {
            h[k] = alpha * a.h[k] + beta * b.h[k];
        }
        return this;
    }

    /** this = a b (this must not be a or b). */
    public Jet mul(Jet a, Jet b) {
        return constant(0).product(a, b, 1);
    }

    /** this += a b (this must not be a or b). */
    public Jet addMul(Jet a, Jet b) {
        return product(a, b, 1);
    }

    /** this −= a b (this must not be a or b). */
    public Jet subMul(Jet a, Jet b) {
        return product(a, b, -1);
    }

    /** this += sign · a b by the product rule (this must not be a or b). */
    private Jet product(Jet a, Jet b, double sign) {
        double av = a.v;
        double bv = b.v;
        int k = 0;
        for (int i = 0; i < n; i++) {
            double agi = a.g[i];
            double bgi = b.g[i];
            for (int j = i; j < n; j++, k++) {
                h[k] += sign * (a.h[k] * bv + b.h[k] * av + agi * b.g[j] + bgi * a.g[j]);
            }
        }
        for (int i = 0; i < n; i++) {
            g[i] += sign * (a.g[i] * bv + b.g[i] * av);
        }
        v += sign * av * bv;
        return this;
    }

    /** this = a x b for jet 3-vectors (this must not be a or b). */
    public static void cross(Jet[] out, Jet[] a, Jet[] b) {
        for (int i = 0; i < 3; i++) {
            int j = (i + 1) % 3;
            int k = (i + 2) % 3;
            out[i].mul(a[j], b[k]).subMul(a[k], b[j]);
        }
    }

    /** out = a · b for jet 3-vectors. */
    public static Jet dot(Jet out, Jet[] a, Jet[] b) {
        out.mul(a[0], b[0]).addMul(a[1], b[1]).addMul(a[2], b[2]);
        return out;
    }

    /** this = f(a) for a scalar function with value f0, slope f1 and curvature f2 at a.v (a may be this). */
    public Jet chain(Jet a, double f0, double f1, double f2) {
        int k = 0;
        for (int i = 0; i < n; i++) {
            double agi = a.g[i];
            for (int j = i; j < n; j++, k++) {
                h[k] = f1 * a.h[k] + f2 * agi * a.g[j];
            }
        }
        for (int i = 0; i < n; i++) {
            g[i] = f1 * a.g[i];
        }
        v = f0;
        return this;
    }

    /** this = sqrt(a). */
    public Jet sqrt(Jet a) {
        double s = Math.sqrt(a.v);
        return chain(a, s, 0.5 / s, -0.25 / (s * a.v));
    }

    /** this = 1 / a. */
    public Jet inverse(Jet a) {
        double r = 1 / a.v;
        return chain(a, r, -r * r, 2 * r * r * r);
    }

    /** this = atan2(y, x) (this must not be y or x). */
    public Jet atan2(Jet y, Jet x) {
        double yv = y.v;
        double xv = x.v;
        double r = xv * xv + yv * yv;
        // partials of atan2: d/dy = x/r, d/dx = -y/r; second: d2/dy2 = -2xy/r², d2/dx2 = 2xy/r²,
        // d2/dxdy = (y² - x²)/r²
        double fy = xv / r;
        double fx = -yv / r;
        double r2 = r * r;
        double fyy = -2 * xv * yv / r2;
        double fxx = 2 * xv * yv / r2;
        double fxy = (yv * yv - xv * xv) / r2;
        int k = 0;
        for (int i = 0; i < n; i++) {
            double ygi = y.g[i];
            double xgi = x.g[i];
            for (int j = i; j < n; j++, k++) {
                h[k] = fy * y.h[k] + fx * x.h[k] + fyy * ygi * y.g[j] + fxx * xgi * x.g[j]
                        + fxy * (xgi * y.g[j] + ygi * x.g[j]);
            }
        }
        for (int i = 0; i < n; i++) {
            g[i] = fy * y.g[i] + fx * x.g[i];
        }
        v = Math.atan2(yv, xv);
        return this;
    }

    /** Hessian entry (i, j). */
    public double hessian(int i, int j) {
        if (i > j) {
            int t = i;
            i = j;
            j = t;
        }
        return h[i * n - i * (i - 1) / 2 + (j - i)];
    }

    /** The full row-major Hessian times {@code s}, written into {@code out} (n x n). */
    public void hessianInto(double[] out, double s) {
        int k = 0;
        for (int i = 0; i < n; i++) {
            for (int j = i; j < n; j++, k++) {
                double val = h[k] * s;
                out[i * n + j] = val;
                out[j * n + i] = val;
            }
        }
    }
}
