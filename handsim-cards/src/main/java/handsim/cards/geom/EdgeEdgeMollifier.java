package handsim.cards.geom;

/**
 * IPC's edge–edge mollifier (Li et al. 2020, sec. 4.3): the barrier of two nearly parallel edges
 * is multiplied by m(c) with c = |(ea1−ea0) × (eb1−eb0)|², m = (2 − c/εx) c/εx below εx and 1
 * above, so that the edge–edge distance's kink at parallel edges does not reach the energy.
 * {@code εx = 1e-3 |ea|² |eb|²} at rest.
 */
public final class EdgeEdgeMollifier {

    private EdgeEdgeMollifier() {
    }

    /** εx of an edge pair from its rest positions x = [ea0, ea1, eb0, eb1]. */
    public static double threshold(double[] rest) {
        double[] ea = Distances.diff(rest, 1, 0);
        double[] eb = Distances.diff(rest, 3, 2);
        return 1e-3 * Distances.dot(ea, ea) * Distances.dot(eb, eb);
    }

    /** m(c) for the scalar c. */
    public static double value(double c, double epsX) {
        if (c < epsX) {
            double r = c / epsX;
            return (2 - r) * r;
        }
        return 1;
    }

    /** m'(c). */
    public static double slope(double c, double epsX) {
        return c < epsX ? 2 / epsX * (1 - c / epsX) : 0;
    }

    /** m''(c). */
    public static double curvature(double c, double epsX) {
        return c < epsX ? -2 / (epsX * epsX) : 0;
    }

    /**
     * m of the four positions, with gradient (12) and Hessian (144) when not null; both are zero
     * when the edges are far from parallel (c ≥ εx).
     */
    public static double evaluate(double[] x, double epsX, double[] grad, double[] hess) {
        // t = ea0 − ea1 and u = eb0 − eb1; n = t × u = ea × eb, each component one fused
        // multiply-add. Nearly parallel edges make each component a cancellation, so the rounding
        // follows the reference's: its value and gradient round n's y component differently.
        double t0 = x[0] - x[3];
        double t1 = x[1] - x[4];
        double t2 = x[2] - x[5];
        double u0 = x[6] - x[9];
        double u1 = x[7] - x[10];
        double u2 = x[8] - x[11];
        double nz = Math.fma(t0, u1, -(t1 * u0));
        double ny = -Math.fma(t0, u2, -(t2 * u0));
        double nx = Math.fma(t1, u2, -(t2 * u1));
        double nyValue = Math.fma(t2, u0, -(t0 * u2));
        double c = nx * nx + nyValue * nyValue + nz * nz;
        if (c >= epsX) {
            if (grad != null) {
                java.util.Arrays.fill(grad, 0, 12, 0.0);
            }
            if (hess != null) {
                java.util.Arrays.fill(hess, 0, 144, 0.0);
            }
            return 1;
        }
        double[] ea = {-t0, -t1, -t2};
        double[] eb = {-u0, -u1, -u2};
        double aa = Distances.dot(ea, ea);
        double bb = Distances.dot(eb, eb);
        double ab = Distances.dot(ea, eb);
        // dc/dea = 2 eb × n, dc/deb = 2 n × ea, written as sums of two products
        double[] dc = {
            -2 * (u1 * nz + u2 * -ny),
            -2 * (-u0 * nz + u2 * nx),
            -2 * (-u0 * -ny - u1 * nx),
            2 * (t1 * nz + t2 * -ny),
            2 * (-t0 * nz + t2 * nx),
            2 * (-t0 * -ny - t1 * nx),
        };
        double m1 = slope(c, epsX);
        double m2 = curvature(c, epsX);
        int[] plus = {1, 3};
        int[] minus = {0, 2};
        if (grad != null) {
            java.util.Arrays.fill(grad, 0, 12, 0.0);
            for (int k = 0; k < 2; k++) {
                for (int d = 0; d < 3; d++) {
                    grad[3 * plus[k] + d] += m1 * dc[3 * k + d];
                    grad[3 * minus[k] + d] -= m1 * dc[3 * k + d];
                }
            }
        }
        if (hess != null) {
            double[] d2c = new double[36];
            for (int i = 0; i < 3; i++) {
                for (int j = 0; j < 3; j++) {
                    double id = i == j ? 1 : 0;
                    d2c[i * 6 + j] = 2 * bb * id - 2 * eb[i] * eb[j];
                    d2c[(3 + i) * 6 + 3 + j] = 2 * aa * id - 2 * ea[i] * ea[j];
                    double mixed = 4 * ea[i] * eb[j] - 2 * eb[i] * ea[j] - 2 * ab * id;
                    d2c[i * 6 + 3 + j] = mixed;
                    d2c[(3 + j) * 6 + i] = mixed;
                }
            }
            java.util.Arrays.fill(hess, 0, 144, 0.0);
            for (int k = 0; k < 2; k++) {
                for (int l = 0; l < 2; l++) {
                    for (int i = 0; i < 3; i++) {
                        for (int j = 0; j < 3; j++) {
                            double hv = m1 * d2c[(3 * k + i) * 6 + 3 * l + j] + m2 * dc[3 * k + i] * dc[3 * l + j];
                            int pk = 3 * plus[k] + i;
                            int mk = 3 * minus[k] + i;
                            int pl = 3 * plus[l] + j;
                            int ml = 3 * minus[l] + j;
                            hess[pk * 12 + pl] += hv;
                            hess[pk * 12 + ml] -= hv;
                            hess[mk * 12 + pl] -= hv;
                            hess[mk * 12 + ml] += hv;
                        }
                    }
                }
            }
        }
        return value(c, epsX);
    }
}
