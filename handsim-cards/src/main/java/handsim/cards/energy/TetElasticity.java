package handsim.cards.energy;

import handsim.cards.linalg.Svd3;

/**
 * Fixed-corotated elasticity of linear tetrahedra (Stomakhin et al. 2012), the default solid of
 * Codim-IPC: Ψ(F) = μ Σ(σᵢ − 1)² + λ/2 (J − 1)², F = Ds Dm⁻¹, energy V̄ Ψ per tetrahedron.
 *
 * <p>The Hessian uses the analytic eigensystem of ∂²Ψ/∂F² in the rotation-variant SVD
 * F = U Σ Vᵀ (Smith et al. 2019): three scaling modes U diag(e) Vᵀ with e the eigenvectors of
 * A = ∂²Ψ/∂σ², and for each pair (i, j) a flip mode (eigenvalue (Ψᵢ − Ψⱼ)/(σᵢ − σⱼ)) and a twist
 * mode (eigenvalue (Ψᵢ + Ψⱼ)/(σᵢ + σⱼ)). Projection clamps those nine eigenvalues at zero, so
 * no 12x12 eigen-decomposition is needed.
 */
public final class TetElasticity implements Energy {

    private final int[] tets;
    private final double[] dmInv;
    private final double[] volume;
    private final double[] mu;
    private final double[] lambda;
    private final int count;

    // workspace (one instance per thread)
    private final double[] f = new double[9];
    private final double[] sig = new double[3];
    private final Svd3 svd = new Svd3();
    private final double[] local = new double[144];
    private final int[] nodes = new int[4];
    private final double[] q = new double[9];
    private final double[] gq = new double[12];
    private final double[] modes = new double[9 * 12];
    private final double[] modeValues = new double[9];
    private final double[] a3 = new double[9];
    private final handsim.cards.linalg.SymmetricEigen eig3 = new handsim.cards.linalg.SymmetricEigen(3);

    /**
     * @param tets   4 node indices per tetrahedron
     * @param rest   rest positions of all nodes
     * @param mu     Lamé μ per tetrahedron (Pa)
     * @param lambda Lamé λ per tetrahedron (Pa)
     */
    public TetElasticity(int[] tets, double[] rest, double[] mu, double[] lambda) {
        this.tets = tets.clone();
        this.count = tets.length / 4;
        this.mu = mu.clone();
        this.lambda = lambda.clone();
        this.dmInv = new double[9 * count];
        this.volume = new double[count];
        double[] dm = new double[9];
        for (int t = 0; t < count; t++) {
            shape(rest, t, dm);
            double det = det3(dm);
            if (!(det > 0)) {
                throw new IllegalArgumentException("tetrahedron " + t + " is inverted or flat at rest (6V = " + det + ")");
            }
            volume[t] = det / 6;
            invert3(dm, det, dmInv, 9 * t);
        }
    }

    /** Rest volume of tetrahedron t of the list {@code tets} over positions {@code x} (m³). */
    public static double volume(double[] x, int[] tets, int t) {
        double[] dm = new double[9];
        int n0 = 3 * tets[4 * t];
        for (int c = 0; c < 3; c++) {
            int nc = 3 * tets[4 * t + 1 + c];
            for (int r = 0; r < 3; r++) {
                dm[r * 3 + c] = x[nc + r] - x[n0 + r];
            }
        }
        return det3(dm) / 6;
    }

    /** Copy sharing the element data, with its own workspace (for another thread). */
    public TetElasticity(TetElasticity other) {
        this.tets = other.tets;
        this.count = other.count;
        this.mu = other.mu;
        this.lambda = other.lambda;
        this.dmInv = other.dmInv;
        this.volume = other.volume;
    }

    @Override
    public int elementCount() {
        return count;
    }

    @Override
    public Energy workspaceCopy() {
        return new TetElasticity(this);
    }

    /** Rest volume of tetrahedron t (m³). */
    public double restVolume(int t) {
        return volume[t];
    }

    private void shape(double[] x, int t, double[] ds) {
        int n0 = 3 * tets[4 * t];
        for (int c = 0; c < 3; c++) {
            int nc = 3 * tets[4 * t + 1 + c];
            for (int r = 0; r < 3; r++) {
                ds[r * 3 + c] = x[nc + r] - x[n0 + r];
            }
        }
    }

    private void deformation(double[] x, int t) {
        double[] ds = q;
        shape(x, t, ds);
        int o = 9 * t;
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                f[r * 3 + c] = ds[r * 3] * dmInv[o + c] + ds[r * 3 + 1] * dmInv[o + 3 + c] + ds[r * 3 + 2] * dmInv[o + 6 + c];
            }
        }
    }

    @Override
    public double value(double[] x, int from, int to) {
        double e = 0;
        for (int t = from; t < to; t++) {
            e += elementValue(x, t);
        }
        return e;
    }

    /** Energy of one tetrahedron (singular values in closed form, no vectors needed). */
    public double elementValue(double[] x, int t) {
        deformation(x, t);
        Svd3.singularValues(f, sig);
        double s0 = sig[0];
        double s1 = sig[1];
        double s2 = sig[2];
        double j = s0 * s1 * s2;
        double psi = mu[t] * ((s0 - 1) * (s0 - 1) + (s1 - 1) * (s1 - 1) + (s2 - 1) * (s2 - 1))
                + 0.5 * lambda[t] * (j - 1) * (j - 1);
        return volume[t] * psi;
    }

    @Override
    public void addGradient(double[] x, int from, int to, double[] g) {
        for (int t = from; t < to; t++) {
            deformation(x, t);
            svd.decompose(f);
            addElementGradient(t, g);
        }
    }

    /** Adds V̄ P : ∂F/∂x of tetrahedron t (its SVD already in {@code svd}). */
    private void addElementGradient(int t, double[] g) {
        double[] s = svd.sigma;
        double j = s[0] * s[1] * s[2];
        double m = mu[t];
        double l = lambda[t];
        // P = U diag(∂Ψ/∂σ) Vᵀ, ∂Ψ/∂σᵢ = 2μ(σᵢ − 1) + λ(J − 1) σⱼσₖ
        double p0 = 2 * m * (s[0] - 1) + l * (j - 1) * s[1] * s[2];
        double p1 = 2 * m * (s[1] - 1) + l * (j - 1) * s[0] * s[2];
        double p2 = 2 * m * (s[2] - 1) + l * (j - 1) * s[0] * s[1];
        double[] u = svd.u;
        double[] v = svd.v;
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                q[r * 3 + c] = u[r * 3] * p0 * v[c * 3] + u[r * 3 + 1] * p1 * v[c * 3 + 1] + u[r * 3 + 2] * p2 * v[c * 3 + 2];
            }
        }
        mapToNodes(t, q, gq);
        for (int k = 0; k < 4; k++) {
            int n = 3 * tets[4 * t + k];
            for (int c = 0; c < 3; c++) {
                g[n + c] += volume[t] * gq[3 * k + c];
            }
        }
    }

    /** ∂(F:Q)/∂x for the four nodes: columns of Q Dm⁻ᵀ, node 0 minus their sum. */
    private void mapToNodes(int t, double[] qm, double[] out) {
        int o = 9 * t;
        for (int a = 0; a < 3; a++) {
            for (int r = 0; r < 3; r++) {
                out[3 * (a + 1) + r] = qm[r * 3] * dmInv[o + a * 3] + qm[r * 3 + 1] * dmInv[o + a * 3 + 1] + qm[r * 3 + 2] * dmInv[o + a * 3 + 2];
            }
        }
        for (int r = 0; r < 3; r++) {
            out[r] = -(out[3 + r] + out[6 + r] + out[9 + r]);
        }
    }

    @Override
    public void addHessian(double[] x, int from, int to, HessianSink sink, boolean project) {
        for (int t = from; t < to; t++) {
            elementHessian(x, t, project);
            send(t, sink);
        }
    }

    @Override
    public void addGradientAndHessian(double[] x, int from, int to, double[] g, HessianSink sink, boolean project) {
        for (int t = from; t < to; t++) {
            deformation(x, t);
            svd.decompose(f);
            addElementGradient(t, g);
            modes(t, project);
            send(t, sink);
        }
    }

    private void send(int t, HessianSink sink) {
        for (int k = 0; k < 4; k++) {
            nodes[k] = tets[4 * t + k];
        }
        sink.add(nodes, 4, local);
    }

    /** The 12x12 Hessian of tetrahedron t into the workspace {@code local}. */
    private void elementHessian(double[] x, int t, boolean project) {
        deformation(x, t);
        svd.decompose(f);
        modes(t, project);
    }

    /** The Hessian from the SVD in {@code svd} by its nine eigen-modes. */
    private void modes(int t, boolean project) {
        double[] s = svd.sigma;
        double m = mu[t];
        double l = lambda[t];
        double j = s[0] * s[1] * s[2];
        double[] dpsi = {
            2 * m * (s[0] - 1) + l * (j - 1) * s[1] * s[2],
            2 * m * (s[1] - 1) + l * (j - 1) * s[0] * s[2],
            2 * m * (s[2] - 1) + l * (j - 1) * s[0] * s[1],
        };
        // scaling modes: A_ii = 2μ + λ (σⱼσₖ)², A_ij = λ σₖ (2J − 1)
        for (int i = 0; i < 3; i++) {
            for (int k = 0; k < 3; k++) {
                if (i == k) {
                    double others = s[(i + 1) % 3] * s[(i + 2) % 3];
                    a3[i * 3 + k] = 2 * m + l * others * others;
                } else {
                    double sk = s[3 - i - k];
                    a3[i * 3 + k] = l * sk * (2 * j - 1);
                }
            }
        }
        eig3.decompose(a3, 3);
        double[] u = svd.u;
        double[] v = svd.v;
        int mode = 0;
        for (int e = 0; e < 3; e++, mode++) {
            for (int r = 0; r < 3; r++) {
                for (int c = 0; c < 3; c++) {
                    double sum = 0;
                    for (int k = 0; k < 3; k++) {
                        sum += u[r * 3 + k] * eig3.vector(e, k) * v[c * 3 + k];
                    }
                    q[r * 3 + c] = sum;
                }
            }
            modeValues[mode] = eig3.value(e);
            mapToNodes(t, q, gq);
            System.arraycopy(gq, 0, modes, 12 * mode, 12);
        }
        // flip and twist modes of each pair (i, j)
        double invSqrt2 = 1 / Math.sqrt(2);
        for (int i = 0; i < 3; i++) {
            for (int k = i + 1; k < 3; k++) {
                int third = 3 - i - k;
                double flip = 2 * m - l * (j - 1) * s[third];
                double sum = s[i] + s[k];
                if (Math.abs(sum) < 1e-12) {
                    sum = Math.copySign(1e-12, sum);
                }
                double twist = (dpsi[i] + dpsi[k]) / sum;
                for (int sign = 1; sign >= -1; sign -= 2, mode++) {
                    for (int r = 0; r < 3; r++) {
                        for (int c = 0; c < 3; c++) {
                            q[r * 3 + c] = invSqrt2 * (u[r * 3 + i] * v[c * 3 + k] + sign * u[r * 3 + k] * v[c * 3 + i]);
                        }
                    }
                    modeValues[mode] = sign > 0 ? flip : twist;
                    mapToNodes(t, q, gq);
                    System.arraycopy(gq, 0, modes, 12 * mode, 12);
                }
            }
        }
        java.util.Arrays.fill(local, 0.0);
        double vol = volume[t];
        for (int md = 0; md < 9; md++) {
            double lam = modeValues[md];
            if (project && lam <= 0) {
                continue;
            }
            lam *= vol;
            int o = 12 * md;
            for (int r = 0; r < 12; r++) {
                double gr = lam * modes[o + r];
                for (int c = r; c < 12; c++) {
                    local[r * 12 + c] += gr * modes[o + c];
                }
            }
        }
        for (int r = 0; r < 12; r++) {
            for (int c = 0; c < r; c++) {
                local[r * 12 + c] = local[c * 12 + r];
            }
        }
    }

    /** Exact or projected 12x12 Hessian of one tetrahedron (a copy), for tests. */
    public double[] elementHessianCopy(double[] x, int t, boolean project) {
        elementHessian(x, t, project);
        return local.clone();
    }

    static double det3(double[] m) {
        return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
    }

    static void invert3(double[] m, double det, double[] out, int o) {
        out[o] = (m[4] * m[8] - m[5] * m[7]) / det;
        out[o + 1] = (m[2] * m[7] - m[1] * m[8]) / det;
        out[o + 2] = (m[1] * m[5] - m[2] * m[4]) / det;
        out[o + 3] = (m[5] * m[6] - m[3] * m[8]) / det;
        out[o + 4] = (m[0] * m[8] - m[2] * m[6]) / det;
        out[o + 5] = (m[2] * m[3] - m[0] * m[5]) / det;
        out[o + 6] = (m[3] * m[7] - m[4] * m[6]) / det;
        out[o + 7] = (m[1] * m[6] - m[0] * m[7]) / det;
        out[o + 8] = (m[0] * m[4] - m[1] * m[3]) / det;
    }
}
