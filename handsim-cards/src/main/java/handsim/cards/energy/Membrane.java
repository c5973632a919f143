package handsim.cards.energy;

import handsim.cards.geom.Jet;
import handsim.cards.linalg.SymmetricEigen;

/**
 * St. Venant–Kirchhoff membrane of a thin shell on the first fundamental form (Codim-IPC's
 * shell membrane): with I = [eᵢ·eⱼ] of the edges e1 = x1 − x0, e2 = x2 − x0 and Ī its rest value,
 * M = Ī⁻¹I − Id is twice the Green strain (up to similarity), and the energy of a triangle is
 * Ā t (λₛ/8 tr(M)² + μ/4 tr(M²)) with plane-stress λₛ = Eν/(1−ν²) and μ = E/(2(1+ν)).
 * Derivatives by {@link Jet}; the 9x9 Hessian is projected by eigen-decomposition.
 */
public final class Membrane implements Energy {

    private final int[] tris;
    private final int count;
    /** Ī⁻¹ entries (p, q, r) per triangle and the two energy coefficients */
    private final double[] restInv;
    private final double[] cTrace;
    private final double[] cSquare;

    private final Jet[] xs = jets(9, 9);
    private final Jet[] e1 = jets(3, 9);
    private final Jet[] e2 = jets(3, 9);
    private final Jet i11 = new Jet(9);
    private final Jet i12 = new Jet(9);
    private final Jet i22 = new Jet(9);
    private final Jet m00 = new Jet(9);
    private final Jet m01 = new Jet(9);
    private final Jet m10 = new Jet(9);
    private final Jet m11 = new Jet(9);
    private final Jet tr = new Jet(9);
    private final Jet energy = new Jet(9);
    private final double[] local = new double[81];
    private final int[] nodes = new int[3];
    private final double[] pos = new double[9];
    private final SymmetricEigen eigen = new SymmetricEigen(9);

    /**
     * @param tris      3 node indices per triangle
     * @param rest      rest positions of all nodes
     * @param young     Young's modulus per triangle (Pa)
     * @param poisson   Poisson's ratio per triangle
     * @param thickness shell thickness per triangle (m)
     */
    public Membrane(int[] tris, double[] rest, double[] young, double[] poisson, double[] thickness) {
        this.tris = tris.clone();
        this.count = tris.length / 3;
        this.restInv = new double[3 * count];
        this.cTrace = new double[count];
        this.cSquare = new double[count];
        for (int t = 0; t < count; t++) {
            double[] a = edge(rest, t, 1);
            double[] b = edge(rest, t, 2);
            double aa = dot(a, a);
            double ab = dot(a, b);
            double bb = dot(b, b);
            double det = aa * bb - ab * ab;
            if (!(det > 0)) {
                throw new IllegalArgumentException("triangle " + t + " is degenerate at rest");
            }
            restInv[3 * t] = bb / det;
            restInv[3 * t + 1] = -ab / det;
            restInv[3 * t + 2] = aa / det;
            double area = 0.5 * Math.sqrt(det);
            double e = young[t];
            double nu = poisson[t];
            double lambdaS = e * nu / (1 - nu * nu);
            double mu = e / (2 * (1 + nu));
            cTrace[t] = area * thickness[t] * lambdaS / 8;
            cSquare[t] = area * thickness[t] * mu / 4;
        }
    }

    /** Shares the element data of {@code other}, with its own scratch memory. */
    private Membrane(Membrane other) {
        this.tris = other.tris;
        this.count = other.count;
        this.restInv = other.restInv;
        this.cTrace = other.cTrace;
        this.cSquare = other.cSquare;
    }

    private static Jet[] jets(int k, int n) {
        Jet[] out = new Jet[k];
        for (int i = 0; i < k; i++) {
            out[i] = new Jet(n);
        }
        return out;
    }

    private double[] edge(double[] x, int t, int corner) {
        int a = 3 * tris[3 * t];
        int b = 3 * tris[3 * t + corner];
        return new double[] {x[b] - x[a], x[b + 1] - x[a + 1], x[b + 2] - x[a + 2]};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    /** Energy of triangle t with derivatives, as a jet in its 9 coordinates. */
    private Jet element(double[] x, int t) {
        for (int k = 0; k < 3; k++) {
            int n = 3 * tris[3 * t + k];
            for (int c = 0; c < 3; c++) {
                xs[3 * k + c].variable(3 * k + c, x[n + c]);
            }
        }
        for (int c = 0; c < 3; c++) {
            e1[c].sub(xs[3 + c], xs[c]);
            e2[c].sub(xs[6 + c], xs[c]);
        }
        Jet.dot(i11, e1, e1);
        Jet.dot(i12, e1, e2);
        Jet.dot(i22, e2, e2);
        double p = restInv[3 * t];
        double q = restInv[3 * t + 1];
        double r = restInv[3 * t + 2];
        m00.linear(p, i11, q, i12, -1);
        m01.linear(p, i12, q, i22, 0);
        m10.linear(q, i11, r, i12, 0);
        m11.linear(q, i12, r, i22, -1);
        tr.add(m00, m11);
        // E = cT tr(M)² + cS (M00² + 2 M01 M10 + M11²)
        energy.mul(tr, tr).scale(energy, cTrace[t] / cSquare[t]);
        energy.addMul(m00, m00).addMul(m11, m11);
        energy.addMul(m01, m10).addMul(m01, m10);
        return energy.scale(energy, cSquare[t]);
    }

    /** Energy of triangle t only. */
    private double elementValue(double[] x, int t) {
        for (int k = 0; k < 3; k++) {
            System.arraycopy(x, 3 * tris[3 * t + k], pos, 3 * k, 3);
        }
        double[] a = {pos[3] - pos[0], pos[4] - pos[1], pos[5] - pos[2]};
        double[] b = {pos[6] - pos[0], pos[7] - pos[1], pos[8] - pos[2]};
        double i11v = dot(a, a);
        double i12v = dot(a, b);
        double i22v = dot(b, b);
        double p = restInv[3 * t];
        double q = restInv[3 * t + 1];
        double r = restInv[3 * t + 2];
        double a00 = p * i11v + q * i12v - 1;
        double a01 = p * i12v + q * i22v;
        double a10 = q * i11v + r * i12v;
        double a11 = q * i12v + r * i22v - 1;
        double trace = a00 + a11;
        return cTrace[t] * trace * trace + cSquare[t] * (a00 * a00 + 2 * a01 * a10 + a11 * a11);
    }

    @Override
    public int elementCount() {
        return count;
    }

    @Override
    public Energy workspaceCopy() {
        return new Membrane(this);
    }

    @Override
    public double value(double[] x, int from, int to) {
        double e = 0;
        for (int t = from; t < to; t++) {
            e += elementValue(x, t);
        }
        return e;
    }

    @Override
    public void addGradient(double[] x, int from, int to, double[] g) {
        for (int t = from; t < to; t++) {
            addElementGradient(element(x, t), t, g);
        }
    }

    private void addElementGradient(Jet e, int t, double[] g) {
        for (int k = 0; k < 3; k++) {
            int n = 3 * tris[3 * t + k];
            for (int c = 0; c < 3; c++) {
                g[n + c] += e.g[3 * k + c];
            }
        }
    }

    @Override
    public void addHessian(double[] x, int from, int to, HessianSink sink, boolean project) {
        addGradientAndHessian(x, from, to, null, sink, project);
    }

    @Override
    public void addGradientAndHessian(double[] x, int from, int to, double[] g, HessianSink sink, boolean project) {
        for (int t = from; t < to; t++) {
            Jet e = element(x, t);
            if (g != null) {
                addElementGradient(e, t, g);
            }
            e.hessianInto(local, 1);
            if (project) {
                eigen.projectToPsd(local, 9);
            }
            for (int k = 0; k < 3; k++) {
                nodes[k] = tris[3 * t + k];
            }
            sink.add(nodes, 3, local);
        }
    }
}
