package handsim.cards.geom;

/**
 * Additive continuous collision detection (Li et al. 2021, Codim-IPC, Alg. 1): advances the
 * primitives along their (mean-free) linear motion in conservative increments
 * η (d − ξ)/l_p, where l_p bounds the relative speed, until the gap falls below (1 − η) of its
 * start. The returned time of impact is in units of the motion (0 = start, 1 = end); a motion
 * that stays clear up to {@code tMax} returns {@link Double#POSITIVE_INFINITY}.
 *
 * <p>Positions are stacked stencils (x0 at the start, x1 at the end) as in {@link Distances}.
 */
public final class AdditiveCcd {

    /**
     * Relative shave of the returned time: the march's sum of increments is exact only to a few
     * rounding errors, and the time of impact must never lie past the true one.
     */
    private static final double ROUNDING_MARGIN = 1e-12;

    /** Iterations after which the current (conservative) time is returned. */
    private static final int MAX_ITERATIONS = 1_000_000;

    private AdditiveCcd() {
    }

    /** Squared distance of a stencil. */
    private interface Distance2 {
        double of(double[] x);
    }

    public static double pointTriangle(double[] x0, double[] x1, double minDistance, double rescaling, double tMax) {
        double[] dx = meanFreeMotion(x0, x1, 4);
        double lp = norm(dx, 0) + Math.sqrt(Math.max(norm2(dx, 1), Math.max(norm2(dx, 2), norm2(dx, 3))));
        return run(x0, dx, lp, x -> Distances.pointTriangle(x, null, null), minDistance, rescaling, tMax);
    }

    public static double edgeEdge(double[] x0, double[] x1, double minDistance, double rescaling, double tMax) {
        double[] dx = meanFreeMotion(x0, x1, 4);
        double lp = Math.sqrt(Math.max(norm2(dx, 0), norm2(dx, 1))) + Math.sqrt(Math.max(norm2(dx, 2), norm2(dx, 3)));
        double min2 = minDistance * minDistance;
        Distance2 d2 = x -> {
            double d = Distances.edgeEdge(x, null, null);
            if (d - min2 <= 0) {
                // only far, nearly parallel edges reach here (closer ones are caught earlier):
                // fall back to the closest endpoints
                d = Math.min(Math.min(dist2(x, 0, 2), dist2(x, 0, 3)), Math.min(dist2(x, 1, 2), dist2(x, 1, 3)));
            }
            return d;
        };
        return run(x0, dx, lp, d2, minDistance, rescaling, tMax);
    }

    public static double pointEdge(double[] x0, double[] x1, double minDistance, double rescaling, double tMax) {
        double[] dx = meanFreeMotion(x0, x1, 3);
        double lp = norm(dx, 0) + Math.sqrt(Math.max(norm2(dx, 1), norm2(dx, 2)));
        return run(x0, dx, lp, x -> Distances.pointEdge(x, null, null), minDistance, rescaling, tMax);
    }

    public static double pointPoint(double[] x0, double[] x1, double minDistance, double rescaling, double tMax) {
        double[] dx = meanFreeMotion(x0, x1, 2);
        double lp = norm(dx, 0) + norm(dx, 1);
        return run(x0, dx, lp, x -> Distances.pointPoint(x, null, null), minDistance, rescaling, tMax);
    }

    private static double run(double[] start, double[] dx, double lp, Distance2 distance2,
                              double minDistance, double rescaling, double tMax) {
        double min2 = minDistance * minDistance;
        double[] x = start.clone();
        double d2 = distance2.of(x);
        if (d2 <= min2) {
            return 0;
        }
        if (lp == 0) {
            return Double.POSITIVE_INFINITY;
        }
        double d = Math.sqrt(d2);
        double dFunc = d2 - min2;
        // (d − ξ) = (d² − ξ²)/(d + ξ): the gap below which the march stops
        double gap = (1 - rescaling) * dFunc / (d + minDistance);
        double toi = 0;
        for (int it = 0; it < MAX_ITERATIONS; it++) {
            double step = rescaling * dFunc / ((d + minDistance) * lp);
            for (int i = 0; i < x.length; i++) {
                x[i] += step * dx[i];
            }
            d2 = distance2.of(x);
            d = Math.sqrt(d2);
            dFunc = d2 - min2;
            if (toi > 0 && dFunc / (d + minDistance) < gap) {
                return toi * (1 - ROUNDING_MARGIN);
            }
            toi += step;
            if (toi > tMax) {
                return Double.POSITIVE_INFINITY;
            }
        }
        return toi * (1 - ROUNDING_MARGIN);
    }

    /** Per-vertex displacement minus its mean (the mean motion changes no distance). */
    private static double[] meanFreeMotion(double[] x0, double[] x1, int nv) {
        double[] dx = new double[3 * nv];
        double[] mean = new double[3];
        for (int v = 0; v < nv; v++) {
            for (int c = 0; c < 3; c++) {
                dx[3 * v + c] = x1[3 * v + c] - x0[3 * v + c];
                mean[c] += dx[3 * v + c];
            }
        }
        for (int c = 0; c < 3; c++) {
            mean[c] /= nv;
        }
        for (int v = 0; v < nv; v++) {
            for (int c = 0; c < 3; c++) {
                dx[3 * v + c] -= mean[c];
            }
        }
        return dx;
    }

    private static double norm2(double[] v, int vertex) {
        double a = v[3 * vertex];
        double b = v[3 * vertex + 1];
        double c = v[3 * vertex + 2];
        return a * a + b * b + c * c;
    }

    private static double norm(double[] v, int vertex) {
        return Math.sqrt(norm2(v, vertex));
    }

    private static double dist2(double[] x, int i, int j) {
        double a = x[3 * i] - x[3 * j];
        double b = x[3 * i + 1] - x[3 * j + 1];
        double c = x[3 * i + 2] - x[3 * j + 2];
        return a * a + b * b + c * c;
    }
}
