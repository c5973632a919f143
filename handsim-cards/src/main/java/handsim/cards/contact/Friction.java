package handsim.cards.contact;

import handsim.cards.energy.HessianSink;
import handsim.cards.geom.DistanceType;
import handsim.cards.geom.Distances.Kernel;

/**
 * Smoothed friction of IPC (Li et al. 2020, sec. 5), lagged once per time step: at the start of
 * the step each active contact fixes its normal force λ = (κ/h²)|∂b/∂d|, its closest-point
 * weights β and a tangent basis P. Over the step, the tangential slip u = Pᵀ Σ βᵢ (xᵢ − xᵢᵗ) costs
 * the dissipative potential μ λ f0(|u|; εv h), entering the incremental potential times h².
 * Its Hessian μλ h² Tᵀ[f1/y I + (f1' − f1/y) ûûᵀ]T is positive semi-definite as it stands.
 * μ depends on the pair: card on card, skin on anything, card on the ground.
 */
public final class Friction {

    private final double epsV;

    private int count;
    private int[] nodeCount = new int[64];
    private int[] nodes = new int[4 * 64];
    private double[] beta = new double[4 * 64];
    private double[] basis = new double[6 * 64];
    private double[] lambda = new double[64];
    private double[] mu = new double[64];
    private double[] start;
    private double h;

    private final double[] local = new double[144];
    private final int[] localNodes = new int[4];
    private final double[] pos = new double[12];

    /** @param epsV slip speed below which friction is smoothed towards static (m/s) */
    public Friction(double epsV) {
        this.epsV = epsV;
    }

    public int size() {
        return count;
    }

    /** Fixes the friction of the contacts of {@code set} (built at {@code xt}) for a step of length h. */
    public void lag(ContactSet set, double[] xt, double kappa, double timeStep) {
        this.h = timeStep;
        this.start = xt.clone();
        count = 0;
        double[] gradD = new double[12];
        for (int c = 0; c < set.count; c++) {
            int k = set.nodeCount(c);
            double d2 = set.distance2(c, xt, gradD, null);
            double s = d2 - set.xi[c] * set.xi[c];
            double force = set.multiplicity[c] * kappa / (h * h) * Math.abs(Barrier.slope(s, set.activation(set.xi[c]))) * 2 * Math.sqrt(d2);
            double coefficient = set.kind[c] == ContactSet.GROUND
                    ? set.mesh().groundFriction(set.node(c, 0))
                    : set.mesh().frictionBetween(set.node(c, 0), set.node(c, k - 1));
            if (!(force > 0) || coefficient == 0) {
                continue;
            }
            grow();
            nodeCount[count] = k;
            for (int i = 0; i < k; i++) {
                nodes[4 * count + i] = set.node(c, i);
                System.arraycopy(xt, 3 * set.node(c, i), pos, 3 * i, 3);
            }
            double[] w = new double[4];
            weights(set, c, w);
            System.arraycopy(w, 0, beta, 4 * count, 4);
            // normal: between the closest points; the tangent basis spans its orthogonal plane
            double[] n = new double[3];
            for (int i = 0; i < k; i++) {
                for (int d = 0; d < 3; d++) {
                    n[d] += w[i] * pos[3 * i + d];
                }
            }
            if (set.kind[c] == ContactSet.GROUND) {
                n = new double[] {0, 0, 1};
            }
            tangentBasis(n, basis, 6 * count);
            lambda[count] = force;
            mu[count] = coefficient;
            count++;
        }
    }

    private void grow() {
        if (count == lambda.length) {
            int cap = 2 * count;
            nodeCount = java.util.Arrays.copyOf(nodeCount, cap);
            nodes = java.util.Arrays.copyOf(nodes, 4 * cap);
            beta = java.util.Arrays.copyOf(beta, 4 * cap);
            basis = java.util.Arrays.copyOf(basis, 6 * cap);
            lambda = java.util.Arrays.copyOf(lambda, cap);
            mu = java.util.Arrays.copyOf(mu, cap);
        }
    }

    /** Closest-point weights of contact c (positions in {@code pos}): Σ wᵢ xᵢ joins the closest points. */
    private void weights(ContactSet set, int c, double[] w) {
        switch (set.kind[c]) {
            case ContactSet.VV -> kernelWeights(Kernel.POINT_POINT, pos, w);
            case ContactSet.EV -> kernelWeights(Kernel.POINT_LINE, pos, w);
            case ContactSet.FV -> kernelWeights(Kernel.POINT_PLANE, pos, w);
            case ContactSet.GROUND -> w[0] = 1;
            default -> {
                DistanceType t = set.mollified[c];
                if (t == null) {
                    kernelWeights(Kernel.LINE_LINE, pos, w);
                } else {
                    double[] sub = new double[12];
                    for (int i = 0; i < t.vertexCount(); i++) {
                        System.arraycopy(pos, 3 * t.vertex(i), sub, 3 * i, 3);
                    }
                    double[] ws = new double[4];
                    kernelWeights(t.kernel(), sub, ws);
                    java.util.Arrays.fill(w, 0);
                    for (int i = 0; i < t.vertexCount(); i++) {
                        w[t.vertex(i)] = ws[i];
                    }
                }
            }
        }
    }

    static void kernelWeights(Kernel kernel, double[] x, double[] w) {
        switch (kernel) {
            case POINT_POINT -> {
                w[0] = 1;
                w[1] = -1;
            }
            case POINT_LINE -> {
                double[] e = sub(x, 2, 1);
                double[] q = sub(x, 0, 1);
                double a = clamp(dot(q, e) / dot(e, e));
                w[0] = 1;
                w[1] = -(1 - a);
                w[2] = -a;
            }
            case POINT_PLANE -> {
                double[] e1 = sub(x, 2, 1);
                double[] e2 = sub(x, 3, 1);
                double[] q = sub(x, 0, 1);
                double a11 = dot(e1, e1);
                double a12 = dot(e1, e2);
                double a22 = dot(e2, e2);
                double r1 = dot(e1, q);
                double r2 = dot(e2, q);
                double det = a11 * a22 - a12 * a12;
                double b1 = (a22 * r1 - a12 * r2) / det;
                double b2 = (a11 * r2 - a12 * r1) / det;
                w[0] = 1;
                w[1] = -(1 - b1 - b2);
                w[2] = -b1;
                w[3] = -b2;
            }
            default -> {
                double[] a = sub(x, 1, 0);
                double[] b = sub(x, 3, 2);
                double[] q = sub(x, 0, 2);
                double aa = dot(a, a);
                double ab = dot(a, b);
                double bb = dot(b, b);
                double ra = -dot(a, q);
                double rb = dot(b, q);
                double det = aa * bb - ab * ab;
                double sa = det > 0 ? clamp((bb * ra + ab * rb) / det) : 0.5;
                double sb = det > 0 ? clamp((ab * ra + aa * rb) / det) : 0.5;
                w[0] = 1 - sa;
                w[1] = sa;
                w[2] = -(1 - sb);
                w[3] = -sb;
            }
        }
    }

    private static double clamp(double v) {
        return Math.max(0, Math.min(1, v));
    }

    private static double[] sub(double[] x, int i, int j) {
        return new double[] {x[3 * i] - x[3 * j], x[3 * i + 1] - x[3 * j + 1], x[3 * i + 2] - x[3 * j + 2]};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    /** Two orthonormal vectors perpendicular to n, written to out[o..o+5]. */
    static void tangentBasis(double[] n, double[] out, int o) {
        double len = Math.sqrt(dot(n, n));
        double[] u = {n[0] / len, n[1] / len, n[2] / len};
        double[] axis = Math.abs(u[0]) < 0.577 ? new double[] {1, 0, 0} : Math.abs(u[1]) < 0.577 ? new double[] {0, 1, 0} : new double[] {0, 0, 1};
        double[] t1 = {u[1] * axis[2] - u[2] * axis[1], u[2] * axis[0] - u[0] * axis[2], u[0] * axis[1] - u[1] * axis[0]};
        double l1 = Math.sqrt(dot(t1, t1));
        for (int d = 0; d < 3; d++) {
            t1[d] /= l1;
        }
        double[] t2 = {u[1] * t1[2] - u[2] * t1[1], u[2] * t1[0] - u[0] * t1[2], u[0] * t1[1] - u[1] * t1[0]};
        System.arraycopy(t1, 0, out, o, 3);
        System.arraycopy(t2, 0, out, o + 3, 3);
    }

    /** Tangential slip of contact c over the step, into u[0..1]. */
    private void slip(int c, double[] x, double[] u) {
        double rx = 0;
        double ry = 0;
        double rz = 0;
        for (int i = 0; i < nodeCount[c]; i++) {
            int n = 3 * nodes[4 * c + i];
            double b = beta[4 * c + i];
            rx += b * (x[n] - start[n]);
            ry += b * (x[n + 1] - start[n + 1]);
            rz += b * (x[n + 2] - start[n + 2]);
        }
        int o = 6 * c;
        u[0] = basis[o] * rx + basis[o + 1] * ry + basis[o + 2] * rz;
        u[1] = basis[o + 3] * rx + basis[o + 4] * ry + basis[o + 5] * rz;
    }

    /** h² Σ μ λ f0(|u|): the friction term of the incremental potential. */
    public double energy(double[] x) {
        double e = 0;
        double[] u = new double[2];
        double eps = epsV * h;
        for (int c = 0; c < count; c++) {
            slip(c, x, u);
            e += mu[c] * lambda[c] * FrictionMollifier.f0(Math.hypot(u[0], u[1]), eps);
        }
        return h * h * e;
    }

    public void addGradient(double[] x, double[] g) {
        double[] u = new double[2];
        double eps = epsV * h;
        for (int c = 0; c < count; c++) {
            slip(c, x, u);
            double y = Math.hypot(u[0], u[1]);
            double s = h * h * mu[c] * lambda[c] * FrictionMollifier.f1OverY(y, eps);
            int o = 6 * c;
            for (int i = 0; i < nodeCount[c]; i++) {
                int n = 3 * nodes[4 * c + i];
                double b = beta[4 * c + i] * s;
                for (int d = 0; d < 3; d++) {
                    g[n + d] += b * (basis[o + d] * u[0] + basis[o + 3 + d] * u[1]);
                }
            }
        }
    }

    public void addHessian(double[] x, HessianSink sink) {
        double[] u = new double[2];
        double eps = epsV * h;
        for (int c = 0; c < count; c++) {
            slip(c, x, u);
            double y = Math.hypot(u[0], u[1]);
            double f1y = FrictionMollifier.f1OverY(y, eps);
            double f2 = FrictionMollifier.f2(y, eps);
            double scale = h * h * mu[c] * lambda[c];
            // inner 2x2: f1/y I + (f1' − f1/y) û ûᵀ
            double m00 = f1y;
            double m01 = 0;
            double m11 = f1y;
            if (y > 0) {
                double k = (f2 - f1y) / (y * y);
                m00 += k * u[0] * u[0];
                m01 += k * u[0] * u[1];
                m11 += k * u[1] * u[1];
            }
            int k = nodeCount[c];
            int n = 3 * k;
            int o = 6 * c;
            for (int i = 0; i < k; i++) {
                for (int a = 0; a < 3; a++) {
                    double ti0 = beta[4 * c + i] * basis[o + a];
                    double ti1 = beta[4 * c + i] * basis[o + 3 + a];
                    for (int j = 0; j < k; j++) {
                        for (int b = 0; b < 3; b++) {
                            double tj0 = beta[4 * c + j] * basis[o + b];
                            double tj1 = beta[4 * c + j] * basis[o + 3 + b];
                            local[(3 * i + a) * n + 3 * j + b] = scale
                                    * (ti0 * (m00 * tj0 + m01 * tj1) + ti1 * (m01 * tj0 + m11 * tj1));
                        }
                    }
                }
            }
            for (int i = 0; i < k; i++) {
                localNodes[i] = nodes[4 * c + i];
            }
            sink.add(localNodes, k, local);
        }
    }

    /** Node pairs coupled by the lagged friction contacts (for the sparsity pattern). */
    public void couplings(PairVisitor pair) {
        for (int c = 0; c < count; c++) {
            for (int i = 0; i < nodeCount[c]; i++) {
                for (int j = i + 1; j < nodeCount[c]; j++) {
                    pair.accept(nodes[4 * c + i], nodes[4 * c + j]);
                }
            }
        }
    }
}
