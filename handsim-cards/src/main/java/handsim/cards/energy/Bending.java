package handsim.cards.energy;

import handsim.cards.geom.DihedralAngle;
import handsim.cards.geom.Jet;
import handsim.cards.linalg.SymmetricEigen;

/**
 * Discrete hinge bending of a thin shell (Grinspun et al. 2003, as in Codim-IPC): per interior
 * edge, k (θ − θ̄)² |ē|/h̄ with k = E t³ / (24 (1 − ν²)), θ the dihedral angle ({@link
 * DihedralAngle}) and h̄ = (Ā1 + Ā2)/(3|ē|) a third of the mean height of the two triangles. The
 * 12x12 Hessian 2w(∇θ∇θᵀ + (θ − θ̄)∇²θ) is projected by eigen-decomposition.
 */
public final class Bending implements Energy {

    private final int[] hinges;
    private final int count;
    private final double[] restAngle;
    private final double[] weight;

    private final DihedralAngle angle = new DihedralAngle();
    private final double[] pos = new double[12];
    private final double[] local = new double[144];
    private final int[] nodes = new int[4];
    private final SymmetricEigen eigen = new SymmetricEigen(12);

    /**
     * @param hinges    4 nodes per hinge: the edge x0–x1, then x2 of triangle (x0, x1, x2) and x3
     *                  of triangle (x1, x0, x3)
     * @param rest      rest positions of all nodes
     * @param stiffness k = E t³ / (24 (1 − ν²)) per hinge (J)
     */
    public Bending(int[] hinges, double[] rest, double[] stiffness) {
        this.hinges = hinges.clone();
        this.count = hinges.length / 4;
        this.restAngle = new double[count];
        this.weight = new double[count];
        for (int h = 0; h < count; h++) {
            gather(rest, h);
            restAngle[h] = DihedralAngle.angle(pos);
            double e2 = dist2(pos, 0, 1);
            double a1 = area(pos, 0, 1, 2);
            double a2 = area(pos, 1, 0, 3);
            weight[h] = stiffness[h] * 3 * e2 / (a1 + a2);
        }
    }

    private void gather(double[] x, int h) {
        for (int k = 0; k < 4; k++) {
            System.arraycopy(x, 3 * hinges[4 * h + k], pos, 3 * k, 3);
        }
    }

    private static double dist2(double[] p, int i, int j) {
        double a = p[3 * i] - p[3 * j];
        double b = p[3 * i + 1] - p[3 * j + 1];
        double c = p[3 * i + 2] - p[3 * j + 2];
        return a * a + b * b + c * c;
    }

    private static double area(double[] p, int i, int j, int k) {
        double[] a = {p[3 * j] - p[3 * i], p[3 * j + 1] - p[3 * i + 1], p[3 * j + 2] - p[3 * i + 2]};
        double[] b = {p[3 * k] - p[3 * i], p[3 * k + 1] - p[3 * i + 1], p[3 * k + 2] - p[3 * i + 2]};
        double cx = a[1] * b[2] - a[2] * b[1];
        double cy = a[2] * b[0] - a[0] * b[2];
        double cz = a[0] * b[1] - a[1] * b[0];
        return 0.5 * Math.sqrt(cx * cx + cy * cy + cz * cz);
    }

    /** Shares the hinge data of {@code other}, with its own scratch memory. */
    private Bending(Bending other) {
        this.hinges = other.hinges;
        this.count = other.count;
        this.restAngle = other.restAngle;
        this.weight = other.weight;
    }

    @Override
    public int elementCount() {
        return count;
    }

    @Override
    public Energy workspaceCopy() {
        return new Bending(this);
    }

    @Override
    public double value(double[] x, int from, int to) {
        double e = 0;
        for (int h = from; h < to; h++) {
            gather(x, h);
            double d = DihedralAngle.angle(pos) - restAngle[h];
            e += weight[h] * d * d;
        }
        return e;
    }

    @Override
    public void addGradient(double[] x, int from, int to, double[] g) {
        for (int h = from; h < to; h++) {
            gather(x, h);
            addHingeGradient(angle.evaluate(pos), h, g);
        }
    }

    private void addHingeGradient(Jet theta, int h, double[] g) {
        double s = 2 * weight[h] * (theta.v - restAngle[h]);
        for (int k = 0; k < 4; k++) {
            int n = 3 * hinges[4 * h + k];
            for (int c = 0; c < 3; c++) {
                g[n + c] += s * theta.g[3 * k + c];
            }
        }
    }

    @Override
    public void addHessian(double[] x, int from, int to, HessianSink sink, boolean project) {
        addGradientAndHessian(x, from, to, null, sink, project);
    }

    @Override
    public void addGradientAndHessian(double[] x, int from, int to, double[] g, HessianSink sink, boolean project) {
        for (int h = from; h < to; h++) {
            gather(x, h);
            Jet theta = angle.evaluate(pos);
            if (g != null) {
                addHingeGradient(theta, h, g);
            }
            double w2 = 2 * weight[h];
            double d = theta.v - restAngle[h];
            theta.hessianInto(local, w2 * d);
            for (int i = 0; i < 12; i++) {
                for (int j = 0; j < 12; j++) {
                    local[i * 12 + j] += w2 * theta.g[i] * theta.g[j];
                }
            }
            if (project) {
                eigen.projectToPsd(local, 12);
            }
            for (int k = 0; k < 4; k++) {
                nodes[k] = hinges[4 * h + k];
            }
            sink.add(nodes, 4, local);
        }
    }

}
