package handsim.sim.island;

import java.util.Arrays;

/**
 * The step's constraint rows, each a line J1 v1 + J2 v2 = rhs + cfm lambda of the two bodies'
 * velocities with its impulse bounded to [lo, hi], in one flat array of {@link #STRIDE} numbers
 * per row: J1 (linear 3, angular 3), J2, the inverse-mass-weighted J^T of both bodies, rhs, cfm,
 * lo, hi. A friction row has its bounds scaled by the impulse of the normal row it names
 * ({@code findex}). Arrays grow when a step has more rows than any before, and never shrink.
 */
final class ConstraintRows {

    static final int J1 = 0, J2 = 6, IMJ1 = 12, IMJ2 = 18, RHS = 24, CFM = 25, LO = 26, HI = 27, STRIDE = 28;

    double[] data;
    int[] body1;
    /** The second body, -1 for none (the static world). */
    int[] body2;
    /** The normal row whose impulse bounds this friction row, -1 for none. */
    int[] findex;
    int count;

    ConstraintRows(int capacity) {
        allocate(Math.max(capacity, 16));
    }

    private void allocate(int capacity) {
        data = data == null ? new double[STRIDE * capacity] : Arrays.copyOf(data, STRIDE * capacity);
        body1 = body1 == null ? new int[capacity] : Arrays.copyOf(body1, capacity);
        body2 = body2 == null ? new int[capacity] : Arrays.copyOf(body2, capacity);
        findex = findex == null ? new int[capacity] : Arrays.copyOf(findex, capacity);
    }

    int capacity() {
        return body1.length;
    }

    void clear() {
        count = 0;
    }

    /**
     * A new row between {@code b1} and {@code b2} (-1: none): J zero, rhs 0, the given cfm,
     * unbounded, no friction index. Returns its offset into {@link #data}.
     */
    int add(int b1, int b2, double cfm) {
        if (count == capacity()) {
            allocate(2 * capacity());
        }
        int i = count++;
        int o = STRIDE * i;
        for (int k = o; k < o + IMJ1; k++) {
            data[k] = 0;
        }
        data[o + RHS] = 0;
        data[o + CFM] = cfm;
        data[o + LO] = Double.NEGATIVE_INFINITY;
        data[o + HI] = Double.POSITIVE_INFINITY;
        body1[i] = b1;
        body2[i] = b2;
        findex[i] = -1;
        return o;
    }
}
