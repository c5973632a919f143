package handsim.export;

import handsim.math.Quat;

/**
 * Tait-Bryan angles about the coordinate axes, applied intrinsically in a given order, as BVH's
 * rotation channels are: {@code R = R_i(a) R_j(b) R_k(c)} for axes {@code (i, j, k)}, a
 * permutation of (0 x, 1 y, 2 z).
 */
final class Euler {

    private Euler() {
    }

    /** The angles (rad) about axes {@code order} whose intrinsic product is {@code q}; the middle one in [-pi/2, pi/2]. */
    static double[] decompose(Quat q, int[] order) {
        double[][] m = matrix(q.normalized());
        int i = order[0], j = order[1], k = order[2];
        // even permutations of (x, y, z) have s = +1: then M[i][k] = sin b, M[j][k] = -sin a cos b, M[i][j] = -cos b sin c
        double s = j == (i + 1) % 3 ? 1 : -1;
        double b = Math.asin(Math.max(-1, Math.min(1, s * m[i][k])));
        double a = Math.atan2(-s * m[j][k], m[k][k]);
        double c = Math.atan2(-s * m[i][j], m[i][i]);
        return new double[] {a, b, c};
    }

    /** The rotation R_order[0](angles[0]) R_order[1](angles[1]) R_order[2](angles[2]). */
    static Quat compose(double[] angles, int[] order) {
        Quat r = Quat.IDENTITY;
        for (int n = 0; n < order.length; n++) {
            double h = 0.5 * angles[n], s = Math.sin(h);
            r = r.mul(new Quat(Math.cos(h), order[n] == 0 ? s : 0, order[n] == 1 ? s : 0, order[n] == 2 ? s : 0));
        }
        return r;
    }

    /** The rotation matrix of unit quaternion {@code q}, rows first. */
    private static double[][] matrix(Quat q) {
        double w = q.w(), x = q.x(), y = q.y(), z = q.z();
        return new double[][] {
            {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    }
}
