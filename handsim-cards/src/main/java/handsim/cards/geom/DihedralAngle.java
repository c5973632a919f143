package handsim.cards.geom;

/**
 * The signed bending angle of a hinge: triangles (x0, x1, x2) and (x1, x0, x3) share the edge
 * x0–x1; θ = atan2((n0 × n1)·ê, n0·n1) with n0 = (x1−x0)×(x2−x0), n1 = (x0−x1)×(x3−x1), zero
 * when the two triangles are flat (the IPC Toolkit's {@code dihedral_angle}). The normals need
 * not be normalised: atan2 is unchanged when both arguments scale by |n0||n1|.
 *
 * <p>One instance holds reusable jets; it is not thread-safe.
 */
public final class DihedralAngle {

    private final Jet[] x = jets(12);
    private final Jet[] e = jets(3);
    private final Jet[] a = jets(3);
    private final Jet[] b = jets(3);
    private final Jet[] n0 = jets(3);
    private final Jet[] n1 = jets(3);
    private final Jet[] c = jets(3);
    private final Jet s = new Jet(12);
    private final Jet cos = new Jet(12);
    private final Jet len = new Jet(12);
    private final Jet tmp = new Jet(12);
    private final Jet theta = new Jet(12);

    private static Jet[] jets(int k) {
        Jet[] out = new Jet[k];
        for (int i = 0; i < k; i++) {
            out[i] = new Jet(12);
        }
        return out;
    }

    /** The angle only; x = [x0, x1, x2, x3]. */
    public static double angle(double[] x) {
        double[] e = Distances.diff(x, 1, 0);
        double[] n0 = Distances.cross(e, Distances.diff(x, 2, 0));
        double[] n1 = Distances.cross(Distances.diff(x, 3, 1), e);
        double[] c = Distances.cross(n0, n1);
        double len = Math.sqrt(Distances.dot(e, e));
        return Math.atan2(Distances.dot(c, e) / len, Distances.dot(n0, n1));
    }

    /** θ with its gradient and Hessian in the 12 coordinates (read them from the returned jet). */
    public Jet evaluate(double[] pos) {
        for (int i = 0; i < 12; i++) {
            x[i].variable(i, pos[i]);
        }
        for (int k = 0; k < 3; k++) {
            e[k].sub(x[3 + k], x[k]);
            a[k].sub(x[6 + k], x[k]);
            b[k].sub(x[9 + k], x[3 + k]);
        }
        Jet.cross(n0, e, a);
        Jet.cross(n1, b, e);
        Jet.cross(c, n0, n1);
        Jet.dot(tmp, e, e);
        len.sqrt(tmp);
        Jet.dot(tmp, c, e);
        s.mul(tmp, cos.inverse(len));
        Jet.dot(cos, n0, n1);
        return theta.atan2(s, cos);
    }
}
