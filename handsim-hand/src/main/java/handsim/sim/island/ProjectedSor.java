package handsim.sim.island;

import static handsim.sim.island.ConstraintRows.ANCHOR_X;
import static handsim.sim.island.ConstraintRows.ANCHOR_Y;
import static handsim.sim.island.ConstraintRows.ANCHOR_Z;
import static handsim.sim.island.ConstraintRows.ANGULAR;
import static handsim.sim.island.ConstraintRows.CFM;
import static handsim.sim.island.ConstraintRows.HI;
import static handsim.sim.island.ConstraintRows.IMJ1;
import static handsim.sim.island.ConstraintRows.IMJ2;
import static handsim.sim.island.ConstraintRows.J1;
import static handsim.sim.island.ConstraintRows.J2;
import static handsim.sim.island.ConstraintRows.LO;
import static handsim.sim.island.ConstraintRows.RHS;
import static handsim.sim.island.ConstraintRows.STRIDE;

import java.util.Arrays;

/**
 * Projected Gauss-Seidel with successive over-relaxation over one island's rows, ODE's SOR-LCP:
 * every row's rhs becomes the velocity error it must remove, rhs/h - J (v/h + M^-1 f); each row is
 * scaled by w / (J M^-1 J^T + cfm) (w the over-relaxation); then every iteration sweeps the rows,
 * each taking the impulse change that zeroes its residual, clamped to its bounds (a friction
 * row's to mu times its normal row's current impulse), and carrying it to the bodies through
 * fc = M^-1 J^T lambda at once. Rows without friction bounds go first; every 8th iteration from
 * the 8th the order is shuffled with the world's generator.
 *
 * <p>Until the first shuffle, consecutive rows of the same two bodies (a joint's rows, a contact's
 * friction pair) are swept as a block: the two bodies' fc is read once at the block's start,
 * kept in local variables while each row of the block takes J fc from it and adds its impulse
 * change, and written back once at the block's end. That is the same Gauss-Seidel update, row
 * after row; it spares each row the store and reload of the fc its predecessor changed. Products
 * are accumulated with fused multiply-adds ({@link Math#fma}: one rounding, the CPU's FMA
 * instruction where it has one).
 */
final class ProjectedSor {

    /** The shuffle period in iterations, ODE's. */
    private static final int SHUFFLE_PERIOD = 8;

    /** The shapes of a block of rows, which pick its sweep (see {@link #findBlocks}). */
    private static final int DENSE_BLOCK = 0, JOINT_BLOCK = 1, ANGULAR_BLOCK = 2;

    /** The constraint accelerations M^-1 J^T lambda, 6 per body. */
    final double[] fc;
    /** Each body's free motion -(v/h + M^-1 f), 6 per body. */
    private final double[] free;
    /** The island's rows in their first sweep order (see {@link #pack}), and per row its body offsets and normal row. */
    private double[] data = new double[0];
    private int[] meta = new int[0];
    /** Each packed row's zeros ({@link ConstraintRows#shape}). */
    private int[] rowShape = new int[0];
    private double[] lambda = new double[0];
    private int[] order = new int[0];
    /** Each assembled row's index in {@link #data}. */
    private int[] position = new int[0];
    /** Block b holds packed rows [blockStart[b], blockStart[b + 1]), of the shape blockShape[b]. */
    private int[] blockStart = new int[1];
    private int[] blockShape = new int[1];
    private int blockCount;

    ProjectedSor(int bodyCount) {
        fc = new double[6 * bodyCount];
        free = new double[6 * bodyCount];
    }

    /** The free motion of every body the rows may touch, once per step. */
    void prepare(RigidBodies bodies, double h) {
        Arrays.fill(fc, 0);
        for (int i = 0; i < bodies.count; i++) {
            if (bodies.active[i]) {
                bodies.freeMotion(i, h, free, 6 * i);
            }
        }
    }

    /**
     * Solves rows [start, end) (one island) in {@code iterations} sweeps; adds their effect to
     * {@link #fc}. The rows are copied in their sweep order (rows without friction bounds first)
     * into the solver's own arrays, so that a sweep reads them one after another.
     */
    void solve(ConstraintRows rows, int start, int end, RigidBodies bodies, double h, int iterations, double sor,
            ShuffleRandom random) {
        int m = end - start;
        if (m == 0) {
            return;
        }
        pack(rows, start, m);
        prepareRows(rows.data, start, m, bodies, 1 / h, sor);
        findBlocks(m);
        boolean shuffled = false;
        for (int it = 0; it < iterations; it++) {
            if (it >= SHUFFLE_PERIOD && it % SHUFFLE_PERIOD == 0) {
                for (int k = 1; k < m; k++) {
                    int swap = random.below(k + 1);
                    int t = order[k];
                    order[k] = order[swap];
                    order[swap] = t;
                }
                shuffled = true;
            }
            if (shuffled) {
                sweep(m);
            } else {
                sweepBlocks();
            }
        }
    }

    /**
     * The blocks of the packed order: runs of rows of the same two bodies, each a
     * {@link #JOINT_BLOCK} (two bodies; a ball's three anchor rows x, y, z, then rows without a
     * linear part), an {@link #ANGULAR_BLOCK} (two bodies, rows without a linear part) or a
     * {@link #DENSE_BLOCK}.
     */
    private void findBlocks(int m) {
        if (blockStart.length < m + 1) {
            blockStart = new int[order.length + 1];
            blockShape = new int[order.length + 1];
        }
        blockCount = 0;
        int start = 0;
        for (int k = 1; k <= m; k++) {
            if (k == m || meta[3 * k] != meta[3 * start] || meta[3 * k + 1] != meta[3 * start + 1]) {
                blockShape[blockCount] = shape(start, k);
                blockStart[blockCount++] = start;
                start = k;
            }
        }
        blockStart[blockCount] = m;
    }

    private int shape(int s, int e) {
        if (meta[3 * s + 1] < 0) {
            return DENSE_BLOCK;
        }
        int k = s;
        boolean anchors = e - s >= 3 && rowShape[s] == ANCHOR_X && rowShape[s + 1] == ANCHOR_Y && rowShape[s + 2] == ANCHOR_Z;
        if (anchors) {
            k += 3;
        }
        for (; k < e; k++) {
            if (rowShape[k] != ANGULAR) {
                return DENSE_BLOCK;
            }
        }
        return anchors ? JOINT_BLOCK : ANGULAR_BLOCK;
    }

    /**
     * The first sweep order of rows [start, start + m): rows without a friction index first, each
     * group in assembly order. {@link #position} holds each row's packed index, {@link #meta}
     * each packed row's 6 b1, 6 b2 (-1 without a body 2) and the packed index of its normal row
     * (-1 for none).
     */
    private void pack(ConstraintRows rows, int start, int m) {
        if (order.length < m) {
            int n = Math.max(m, 2 * order.length);
            order = new int[n];
            position = new int[n];
            lambda = new double[n];
            meta = new int[3 * n];
            rowShape = new int[n];
            data = new double[STRIDE * n];
        }
        int frictionRows = 0;
        for (int i = start; i < start + m; i++) {
            frictionRows += rows.findex[i] >= 0 ? 1 : 0;
        }
        int head = 0, tail = m - frictionRows;
        for (int i = start; i < start + m; i++) {
            int p = rows.findex[i] >= 0 ? tail++ : head++;
            position[i - start] = p;
            rowShape[p] = rows.shape[i];
            meta[3 * p] = 6 * rows.body1[i];
            meta[3 * p + 1] = rows.body2[i] < 0 ? -1 : 6 * rows.body2[i];
        }
        for (int i = start; i < start + m; i++) {
            int f = rows.findex[i];
            meta[3 * position[i - start] + 2] = f < 0 ? -1 : position[f - start];
        }
    }

    /**
     * The packed rows from assembled rows [start, start + m) of {@code src}, each of the bodies at
     * fc offsets a and b (-1: none): rhs and cfm made rates (times 1/h), rhs += J (-(v/h + M^-1 f))
     * of the two bodies, iMJ = M^-1 J^T, and then the row, its rhs and cfm scaled by
     * w / (J M^-1 J^T + cfm); every impulse zero and the sweep order the packed order.
     */
    private void prepareRows(double[] src, int start, int m, RigidBodies bodies, double rh, double sor) {
        double[] d = data, free = this.free, ii = bodies.inverseInertiaWorld, inverseMass = bodies.inverseMass;
        for (int row = 0; row < m; row++) {
            int p = position[row];
            int s = STRIDE * (start + row), o = STRIDE * p, a = meta[3 * p], b = meta[3 * p + 1];
            lambda[p] = 0;
            order[p] = p;
            double rhs = src[s + RHS] * rh;
            double cfm = src[s + CFM] * rh;
            double j0 = src[s], j1 = src[s + 1], j2 = src[s + 2], j3 = src[s + 3], j4 = src[s + 4], j5 = src[s + 5];
            double k0 = 0, k1 = 0, k2 = 0, k3 = 0, k4 = 0, k5 = 0;
            if (b >= 0) {
                k0 = src[s + J2];
                k1 = src[s + J2 + 1];
                k2 = src[s + J2 + 2];
                k3 = src[s + J2 + 3];
                k4 = src[s + J2 + 4];
                k5 = src[s + J2 + 5];
            }
            // J (-(v/h + M^-1 f)), and J M^-1 J^T with iMJ written, each summed term by term
            double sum = accumulate(0, j0, j1, j2, j3, j4, j5, free, a);
            double jmj = inverseMassTimes(0, j0, j1, j2, j3, j4, j5, inverseMass[a / 6], ii, 9 * (a / 6), d, o + IMJ1);
            if (b >= 0) {
                sum = accumulate(sum, k0, k1, k2, k3, k4, k5, free, b);
                jmj = inverseMassTimes(jmj, k0, k1, k2, k3, k4, k5, inverseMass[b / 6], ii, 9 * (b / 6), d, o + IMJ2);
            } else {
                Arrays.fill(d, o + IMJ2, o + IMJ2 + 6, 0);
            }
            rhs += sum;
            double ad = sor / (jmj + cfm);
            d[o + CFM] = cfm * ad;
            d[o + RHS] = rhs * ad;
            d[o + LO] = src[s + LO];
            d[o + HI] = src[s + HI];
            scaled(d, o + J1, ad, j0, j1, j2, j3, j4, j5);
            scaled(d, o + J2, ad, k0, k1, k2, k3, k4, k5);
        }
    }

    /** sum + x . (j0 ... j5), x from {@code at}, added term by term. */
    private static double accumulate(double sum, double j0, double j1, double j2, double j3, double j4, double j5, double[] x, int at) {
        sum += j0 * x[at];
        sum += j1 * x[at + 1];
        sum += j2 * x[at + 2];
        sum += j3 * x[at + 3];
        sum += j4 * x[at + 4];
        sum += j5 * x[at + 5];
        return sum;
    }

    /**
     * One body's part of iMJ = M^-1 J^T (inverse mass {@code im}, world inverse inertia at
     * {@code ii[n]}) into {@code d[out...]}; returns sum + that part of J M^-1 J^T, added term by
     * term.
     */
    private static double inverseMassTimes(double sum, double j0, double j1, double j2, double j3, double j4, double j5, double im,
            double[] ii, int n, double[] d, int out) {
        double m0 = im * j0, m1 = im * j1, m2 = im * j2;
        double m3 = ii[n] * j3 + ii[n + 1] * j4 + ii[n + 2] * j5;
        double m4 = ii[n + 3] * j3 + ii[n + 4] * j4 + ii[n + 5] * j5;
        double m5 = ii[n + 6] * j3 + ii[n + 7] * j4 + ii[n + 8] * j5;
        store(d, out, m0, m1, m2, m3, m4, m5);
        sum += m0 * j0;
        sum += m1 * j1;
        sum += m2 * j2;
        sum += m3 * j3;
        sum += m4 * j4;
        sum += m5 * j5;
        return sum;
    }

    private static void scaled(double[] d, int o, double ad, double j0, double j1, double j2, double j3, double j4, double j5) {
        store(d, o, j0 * ad, j1 * ad, j2 * ad, j3 * ad, j4 * ad, j5 * ad);
    }

    /** Six values into {@code to[at...]}: a body's six velocity (or row) components. */
    private static void store(double[] to, int at, double v0, double v1, double v2, double v3, double v4, double v5) {
        to[at] = v0;
        to[at + 1] = v1;
        to[at + 2] = v2;
        to[at + 3] = v3;
        to[at + 4] = v4;
        to[at + 5] = v5;
    }

    /**
     * One Gauss-Seidel sweep over the packed rows in their order, block by block (see the class
     * comment): the block's bodies' fc read once, held in locals through the block's rows, and
     * written once after it. A joint's block leaves out the terms its rows have as zeros (its
     * shape, {@link #findBlocks}), with the dense sum's rounding: a zero product adds nothing to a
     * sum, an fma with a zero addend rounds once, and a zero term of M^-1 J^T leaves fc as it is.
     */
    private void sweepBlocks() {
        double[] d = data;
        double[] lambda = this.lambda;
        double[] f = fc;
        for (int bl = 0; bl < blockCount; bl++) {
            int s = blockStart[bl];
            int e = blockStart[bl + 1];
            int a = meta[3 * s];
            int b = meta[3 * s + 1];
            double a0 = f[a], a1 = f[a + 1], a2 = f[a + 2], a3 = f[a + 3], a4 = f[a + 4], a5 = f[a + 5];
            double c0 = 0, c1 = 0, c2 = 0, c3 = 0, c4 = 0, c5 = 0;
            if (b >= 0) {
                c0 = f[b];
                c1 = f[b + 1];
                c2 = f[b + 2];
                c3 = f[b + 3];
                c4 = f[b + 4];
                c5 = f[b + 5];
            }
            int k = s;
            int shape = blockShape[bl];
            if (shape == JOINT_BLOCK) {
                // the anchor row along x: J's linear part (j0, 0, 0), its angular x term 0
                int o = STRIDE * k;
                double sum = a0 * d[o] + Math.fma(a5, d[o + 5], a4 * d[o + 4]);
                sum += c0 * d[o + J2] + Math.fma(c5, d[o + J2 + 5], c4 * d[o + J2 + 4]);
                double delta = project(lambda, k, d, o, sum);
                a0 = Math.fma(delta, d[o + IMJ1], a0);
                a3 = Math.fma(delta, d[o + IMJ1 + 3], a3);
                a4 = Math.fma(delta, d[o + IMJ1 + 4], a4);
                a5 = Math.fma(delta, d[o + IMJ1 + 5], a5);
                c0 = Math.fma(delta, d[o + IMJ2], c0);
                c3 = Math.fma(delta, d[o + IMJ2 + 3], c3);
                c4 = Math.fma(delta, d[o + IMJ2 + 4], c4);
                c5 = Math.fma(delta, d[o + IMJ2 + 5], c5);
                // along y
                o += STRIDE;
                sum = (a1 * d[o + 1] + a3 * d[o + 3]) + a5 * d[o + 5];
                sum += (c1 * d[o + J2 + 1] + c3 * d[o + J2 + 3]) + c5 * d[o + J2 + 5];
                delta = project(lambda, k + 1, d, o, sum);
                a1 = Math.fma(delta, d[o + IMJ1 + 1], a1);
                a3 = Math.fma(delta, d[o + IMJ1 + 3], a3);
                a4 = Math.fma(delta, d[o + IMJ1 + 4], a4);
                a5 = Math.fma(delta, d[o + IMJ1 + 5], a5);
                c1 = Math.fma(delta, d[o + IMJ2 + 1], c1);
                c3 = Math.fma(delta, d[o + IMJ2 + 3], c3);
                c4 = Math.fma(delta, d[o + IMJ2 + 4], c4);
                c5 = Math.fma(delta, d[o + IMJ2 + 5], c5);
                // along z
                o += STRIDE;
                sum = Math.fma(a3, d[o + 3], a2 * d[o + 2]) + a4 * d[o + 4];
                sum += Math.fma(c3, d[o + J2 + 3], c2 * d[o + J2 + 2]) + c4 * d[o + J2 + 4];
                delta = project(lambda, k + 2, d, o, sum);
                a2 = Math.fma(delta, d[o + IMJ1 + 2], a2);
                a3 = Math.fma(delta, d[o + IMJ1 + 3], a3);
                a4 = Math.fma(delta, d[o + IMJ1 + 4], a4);
                a5 = Math.fma(delta, d[o + IMJ1 + 5], a5);
                c2 = Math.fma(delta, d[o + IMJ2 + 2], c2);
                c3 = Math.fma(delta, d[o + IMJ2 + 3], c3);
                c4 = Math.fma(delta, d[o + IMJ2 + 4], c4);
                c5 = Math.fma(delta, d[o + IMJ2 + 5], c5);
                k += 3;
            }
            if (shape != DENSE_BLOCK) {
                // rows without a linear part
                for (; k < e; k++) {
                    int o = STRIDE * k;
                    double sum = a3 * d[o + 3] + Math.fma(a5, d[o + 5], a4 * d[o + 4]);
                    sum += c3 * d[o + J2 + 3] + Math.fma(c5, d[o + J2 + 5], c4 * d[o + J2 + 4]);
                    double delta = project(lambda, k, d, o, sum);
                    a3 = Math.fma(delta, d[o + IMJ1 + 3], a3);
                    a4 = Math.fma(delta, d[o + IMJ1 + 4], a4);
                    a5 = Math.fma(delta, d[o + IMJ1 + 5], a5);
                    c3 = Math.fma(delta, d[o + IMJ2 + 3], c3);
                    c4 = Math.fma(delta, d[o + IMJ2 + 4], c4);
                    c5 = Math.fma(delta, d[o + IMJ2 + 5], c5);
                }
            }
            for (; k < e; k++) {
                int o = STRIDE * k;
                double sum = dot(d, o, a0, a1, a2, a3, a4, a5);
                if (b >= 0) {
                    sum += dot(d, o + J2, c0, c1, c2, c3, c4, c5);
                }
                double delta = projectBounded(lambda, k, d, o, sum, meta[3 * k + 2]);
                a0 = Math.fma(delta, d[o + IMJ1], a0);
                a1 = Math.fma(delta, d[o + IMJ1 + 1], a1);
                a2 = Math.fma(delta, d[o + IMJ1 + 2], a2);
                a3 = Math.fma(delta, d[o + IMJ1 + 3], a3);
                a4 = Math.fma(delta, d[o + IMJ1 + 4], a4);
                a5 = Math.fma(delta, d[o + IMJ1 + 5], a5);
                if (b >= 0) {
                    c0 = Math.fma(delta, d[o + IMJ2], c0);
                    c1 = Math.fma(delta, d[o + IMJ2 + 1], c1);
                    c2 = Math.fma(delta, d[o + IMJ2 + 2], c2);
                    c3 = Math.fma(delta, d[o + IMJ2 + 3], c3);
                    c4 = Math.fma(delta, d[o + IMJ2 + 4], c4);
                    c5 = Math.fma(delta, d[o + IMJ2 + 5], c5);
                }
            }
            store(f, a, a0, a1, a2, a3, a4, a5);
            if (b >= 0) {
                store(f, b, c0, c1, c2, c3, c4, c5);
            }
        }
    }

    /**
     * One Gauss-Seidel sweep over the island's rows in {@link #order}, row by row (the shuffled
     * iterations). The two bodies' parts of J fc are summed pairwise rather than left to right,
     * and each body's fc is read once.
     */
    private void sweep(int m) {
        double[] d = data;
        double[] lambda = this.lambda;
        int[] meta = this.meta;
        double[] f = fc;
        for (int k = 0; k < m; k++) {
            int i = order[k];
            int o = STRIDE * i;
            int a = meta[3 * i];
            int b = meta[3 * i + 1];
            double a0 = f[a], a1 = f[a + 1], a2 = f[a + 2], a3 = f[a + 3], a4 = f[a + 4], a5 = f[a + 5];
            double s = dot(d, o, a0, a1, a2, a3, a4, a5);
            double c0 = 0, c1 = 0, c2 = 0, c3 = 0, c4 = 0, c5 = 0;
            if (b >= 0) {
                c0 = f[b];
                c1 = f[b + 1];
                c2 = f[b + 2];
                c3 = f[b + 3];
                c4 = f[b + 4];
                c5 = f[b + 5];
                s += dot(d, o + J2, c0, c1, c2, c3, c4, c5);
            }
            double delta = projectBounded(lambda, i, d, o, s, meta[3 * i + 2]);
            f[a] = Math.fma(delta, d[o + IMJ1], a0);
            f[a + 1] = Math.fma(delta, d[o + IMJ1 + 1], a1);
            f[a + 2] = Math.fma(delta, d[o + IMJ1 + 2], a2);
            f[a + 3] = Math.fma(delta, d[o + IMJ1 + 3], a3);
            f[a + 4] = Math.fma(delta, d[o + IMJ1 + 4], a4);
            f[a + 5] = Math.fma(delta, d[o + IMJ1 + 5], a5);
            if (b >= 0) {
                f[b] = Math.fma(delta, d[o + IMJ2], c0);
                f[b + 1] = Math.fma(delta, d[o + IMJ2 + 1], c1);
                f[b + 2] = Math.fma(delta, d[o + IMJ2 + 2], c2);
                f[b + 3] = Math.fma(delta, d[o + IMJ2 + 3], c3);
                f[b + 4] = Math.fma(delta, d[o + IMJ2 + 4], c4);
                f[b + 5] = Math.fma(delta, d[o + IMJ2 + 5], c5);
            }
        }
    }

    /** {@link #project(double[], int, double[], int, double, double, double)} within the row's own bounds [LO, HI]. */
    private static double project(double[] lambda, int k, double[] d, int o, double sum) {
        return project(lambda, k, d, o, sum, d[o + LO], d[o + HI]);
    }

    /** {@link #project}, a friction row's bounds mu times its normal row's impulse (normal &gt;= 0). */
    private static double projectBounded(double[] lambda, int k, double[] d, int o, double sum, int normal) {
        if (normal < 0) {
            return project(lambda, k, d, o, sum);
        }
        double hi = Math.abs(d[o + HI] * lambda[normal]);
        return project(lambda, k, d, o, sum, -hi, hi);
    }

    /**
     * Moves row k's impulse by the change that zeroes its residual (rhs - cfm lambda - J fc, with
     * J fc = {@code sum}), clamped to [lo, hi]; returns the change made.
     */
    private static double project(double[] lambda, int k, double[] d, int o, double sum, double lo, double hi) {
        double old = lambda[k];
        double delta = (d[o + RHS] - old * d[o + CFM]) - sum;
        double next = old + delta;
        if (next < lo) {
            delta = lo - old;
            next = lo;
        } else if (next > hi) {
            delta = hi - old;
            next = hi;
        }
        lambda[k] = next;
        return delta;
    }

    /** J x of one body's part of a row (6 numbers of {@code d} from {@code o}), in three pairs. */
    private static double dot(double[] d, int o, double x0, double x1, double x2, double x3, double x4, double x5) {
        return Math.fma(x1, d[o + 1], x0 * d[o]) + Math.fma(x3, d[o + 3], x2 * d[o + 2]) + Math.fma(x5, d[o + 5], x4 * d[o + 4]);
    }
}
