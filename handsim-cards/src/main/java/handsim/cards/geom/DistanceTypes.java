package handsim.cards.geom;

/**
 * Classifies the closest features of a point–edge, point–triangle or edge–edge pair, following
 * the decisions of the IPC Toolkit (its {@code distance_type} functions) so that a pair at a
 * feature boundary falls on the same side as in the reference.
 */
public final class DistanceTypes {

    /** Edges count as parallel when sin² of their angle is below this (relative to their lengths²). */
    private static final double PARALLEL_THRESHOLD = 2.5e-16;

    private DistanceTypes() {
    }

    /** x = [p, e0, e1]. */
    public static DistanceType pointEdge(double[] x) {
        double ex = x[6] - x[3];
        double ey = x[7] - x[4];
        double ez = x[8] - x[5];
        double len2 = ex * ex + ey * ey + ez * ez;
        if (len2 == 0) {
            return DistanceType.PE_P_E0;
        }
        double ratio = (ex * (x[0] - x[3]) + ey * (x[1] - x[4]) + ez * (x[2] - x[5])) / len2;
        if (ratio < 0) {
            return DistanceType.PE_P_E0;
        } else if (ratio > 1) {
            return DistanceType.PE_P_E1;
        }
        return DistanceType.PE_P_E;
    }

    /**
     * x = [p, t0, t1, t2]. For each edge, the point's coordinates in the basis (edge, edge ×
     * normal) decide whether the edge's interior is closest; otherwise a vertex or the face.
     */
    public static DistanceType pointTriangle(double[] x) {
        double[] p = {x[0], x[1], x[2]};
        double[][] t = {{x[3], x[4], x[5]}, {x[6], x[7], x[8]}, {x[9], x[10], x[11]}};
        double[] normal = Distances.cross(sub(t[1], t[0]), sub(t[2], t[0]));
        double[] s = new double[3];
        for (int e = 0; e < 3; e++) {
            double[] a = t[e];
            double[] b = t[(e + 1) % 3];
            double[] r0 = sub(b, a);
            double[] r1 = Distances.cross(r0, normal);
            double[] d = sub(p, a);
            // least-squares coordinates: (B B^T) c = B d, B = [r0; r1]
            double m00 = Distances.dot(r0, r0);
            double m01 = Distances.dot(r0, r1);
            double m11 = Distances.dot(r1, r1);
            double b0 = Distances.dot(r0, d);
            double b1 = Distances.dot(r1, d);
            double det = m00 * m11 - m01 * m01;
            double c0 = (m11 * b0 - m01 * b1) / det;
            double c1 = (m00 * b1 - m01 * b0) / det;
            if (c0 > 0.0 && c0 < 1.0 && c1 >= 0.0) {
                return e == 0 ? DistanceType.PT_P_E0 : e == 1 ? DistanceType.PT_P_E1 : DistanceType.PT_P_E2;
            }
            s[e] = c0;
        }
        if (s[0] <= 0.0 && s[2] >= 1.0) {
            return DistanceType.PT_P_T0;
        } else if (s[1] <= 0.0 && s[0] >= 1.0) {
            return DistanceType.PT_P_T1;
        } else if (s[2] <= 0.0 && s[1] >= 1.0) {
            return DistanceType.PT_P_T2;
        }
        return DistanceType.PT_P_T;
    }

    /** x = [ea0, ea1, eb0, eb1]; the closest points of the two segments (geomalgorithms a07). */
    public static DistanceType edgeEdge(double[] x) {
        double[] ea0 = {x[0], x[1], x[2]};
        double[] ea1 = {x[3], x[4], x[5]};
        double[] eb0 = {x[6], x[7], x[8]};
        double[] eb1 = {x[9], x[10], x[11]};
        double[] u = sub(ea1, ea0);
        double[] v = sub(eb1, eb0);
        double[] w = sub(ea0, eb0);
        double a = Distances.dot(u, u);
        double b = Distances.dot(u, v);
        double c = Distances.dot(v, v);
        double d = Distances.dot(u, w);
        double e = Distances.dot(v, w);
        double big = a * c - b * b;
        if (a == 0.0 && c == 0.0) {
            return DistanceType.EE_EA0_EB0;
        } else if (a == 0.0) {
            return DistanceType.EE_EA0_EB;
        } else if (c == 0.0) {
            return DistanceType.EE_EA_EB0;
        }
        double[] uxv = Distances.cross(u, v);
        if (Distances.dot(uxv, uxv) < PARALLEL_THRESHOLD * a * c) {
            return parallel(ea0, ea1, eb0, eb1);
        }
        DistanceType fallback = DistanceType.EE_EA_EB;
        double sN = b * e - c * d;
        double tN;
        double tD;
        if (sN <= 0.0) {
            tN = e;
            tD = c;
            fallback = DistanceType.EE_EA0_EB;
        } else if (sN >= big) {
            tN = e + b;
            tD = c;
            fallback = DistanceType.EE_EA1_EB;
        } else {
            tN = a * e - b * d;
            tD = big;
        }
        if (tN <= 0.0) {
            if (-d <= 0.0) {
                return DistanceType.EE_EA0_EB0;
            } else if (-d >= a) {
                return DistanceType.EE_EA1_EB0;
            }
            return DistanceType.EE_EA_EB0;
        } else if (tN >= tD) {
            if (-d + b <= 0.0) {
                return DistanceType.EE_EA0_EB1;
            } else if (-d + b >= a) {
                return DistanceType.EE_EA1_EB1;
            }
            return DistanceType.EE_EA_EB1;
        }
        return fallback;
    }

    /** Parallel segments: closest features from eb0, eb1 projected onto ea. */
    private static DistanceType parallel(double[] ea0, double[] ea1, double[] eb0, double[] eb1) {
        double[] ea = sub(ea1, ea0);
        double len2 = Distances.dot(ea, ea);
        double alpha = Distances.dot(sub(eb0, ea0), ea) / len2;
        double beta = Distances.dot(sub(eb1, ea0), ea) / len2;
        int eac; // 0: ea0, 1: ea1, 2: edge a
        int ebc; // 0: eb0, 1: eb1, 2: edge b
        if (alpha < 0) {
            eac = (0 <= beta && beta <= 1) ? 2 : 0;
            ebc = (beta <= alpha) ? 0 : (beta <= 1 ? 1 : 2);
        } else if (alpha > 1) {
            eac = (0 <= beta && beta <= 1) ? 2 : 1;
            ebc = (beta >= alpha) ? 0 : (0 <= beta ? 1 : 2);
        } else {
            eac = 2;
            ebc = 0;
        }
        DistanceType[][] table = {
            {DistanceType.EE_EA0_EB0, DistanceType.EE_EA0_EB1, DistanceType.EE_EA0_EB},
            {DistanceType.EE_EA1_EB0, DistanceType.EE_EA1_EB1, DistanceType.EE_EA1_EB},
            {DistanceType.EE_EA_EB0, DistanceType.EE_EA_EB1, DistanceType.EE_EA_EB},
        };
        return table[eac][ebc];
    }

    private static double[] sub(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }
}
