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

    /**
     * The zeros a row's J has by construction, the same in J1 and J2 (linear 0-2, angular 3-5):
     * none; a ball's anchor row along x, y or z (one linear term, the angular term about that
     * axis zero); no linear part (a hinge's and a universal joint's angular rows, the stops).
     */
    static final int DENSE = 0, ANCHOR_X = 1, ANCHOR_Y = 2, ANCHOR_Z = 3, ANGULAR = 4;

    /** The indices (of 6) at which J1 and J2 of a row of {@code shape} are zero. */
    static int[] zeros(int shape) {
        return switch (shape) {
            case ANCHOR_X -> new int[] {1, 2, 3};
            case ANCHOR_Y -> new int[] {0, 2, 4};
            case ANCHOR_Z -> new int[] {0, 1, 5};
            case ANGULAR -> new int[] {0, 1, 2};
            default -> new int[0];
        };
    }

    double[] data;
    int[] body1;
    /** The second body, -1 for none (the static world). */
    int[] body2;
    /** The normal row whose impulse bounds this friction row, -1 for none. */
    int[] findex;
    /** Each row's zeros ({@link #DENSE}, {@link #ANCHOR_X} ...), set by the assembly that wrote them. */
    int[] shape;
    int count;

    ConstraintRows(int capacity) {
        allocate(Math.max(capacity, 16));
    }

    private void allocate(int capacity) {
        data = data == null ? new double[STRIDE * capacity] : Arrays.copyOf(data, STRIDE * capacity);
        body1 = body1 == null ? new int[capacity] : Arrays.copyOf(body1, capacity);
        body2 = body2 == null ? new int[capacity] : Arrays.copyOf(body2, capacity);
        findex = findex == null ? new int[capacity] : Arrays.copyOf(findex, capacity);
        shape = shape == null ? new int[capacity] : Arrays.copyOf(shape, capacity);
    }

    int capacity() {
        return body1.length;
    }

    void clear() {
        count = 0;
    }

    /**
     * A new row between {@code b1} and {@code b2} (-1: none): J zero, rhs 0, the given cfm,
     * unbounded, no friction index, {@link #DENSE}. Returns its offset into {@link #data}.
     */
    int add(int b1, int b2, double cfm) {
        return add(b1, b2, cfm, DENSE);
    }

    /** {@link #add(int, int, double)}, of a shape whose zeros the caller's J keeps. */
    int add(int b1, int b2, double cfm, int shape) {
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
        this.shape[i] = shape;
        return o;
    }
}
