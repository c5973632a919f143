package handsim.sim.island;

import java.util.Arrays;

/**
 * The joints between the island's bodies, in the order they were created in the engine (which
 * fixes ODE's traversal order, and so the rows' order): ball joints, hinges and universal joints
 * as ODE formulates them, and the limits of a ball joint's three Euler angles, a joint of its
 * own (ODE's user-mode angular motor). Anchors and axes are given in each body's frame, the
 * anchors relative to the body's centre of mass (m); axes are unit vectors; all of them in the
 * configuration the joints were created in, where every body is unrotated. A hinge's and a
 * universal joint's axes are the engine's (the model's, negated), so that the engine's joint
 * angle is the model's; its stops are the model's limits (rad).
 */
public final class Articulation {

    static final int BALL = 0, HINGE = 1, UNIVERSAL = 2, EULER_LIMITS = 3;

    int count;
    int[] type = new int[8];
    int[] body1 = new int[8];
    int[] body2 = new int[8];
    /** The joint's first DOF in the angle arrays the step is given. */
    int[] firstDof = new int[8];
    double[] anchor1 = new double[24];
    double[] anchor2 = new double[24];
    double[] axis1 = new double[24];
    double[] axis2 = new double[24];
    /** Up to three stops per joint (rad): lower and upper per axis. */
    double[] lower = new double[24];
    double[] upper = new double[24];
    /** tan(stop / 2) of each stop, to test a hinge's or universal joint's stops without the arc tangent. */
    double[] lowerHalfTangent = new double[24];
    double[] upperHalfTangent = new double[24];
    /** A universal joint's cross frames at rest (8 per joint, see JointAngles.universal). */
    double[] crossAtRest = new double[64];

    /** A ball joint; returns its index. */
    public int addBall(int parent, int child, double[] anchorInParent, double[] anchorInChild) {
        int j = add(BALL, parent, child, -1);
        System.arraycopy(anchorInParent, 0, anchor1, 3 * j, 3);
        System.arraycopy(anchorInChild, 0, anchor2, 3 * j, 3);
        return j;
    }

    /** A hinge about {@code axisInParent} / {@code axisInChild}, its angle the DOF {@code dof}, stopped at [lo, hi]. */
    public int addHinge(int parent, int child, double[] anchorInParent, double[] anchorInChild, double[] axisInParent,
            double[] axisInChild, int dof, double lo, double hi) {
        int j = add(HINGE, parent, child, dof);
        System.arraycopy(anchorInParent, 0, anchor1, 3 * j, 3);
        System.arraycopy(anchorInChild, 0, anchor2, 3 * j, 3);
        System.arraycopy(axisInParent, 0, axis1, 3 * j, 3);
        System.arraycopy(axisInChild, 0, axis2, 3 * j, 3);
        setStop(j, 0, lo, hi);
        return j;
    }

    private void setStop(int j, int axis, double lo, double hi) {
        lower[3 * j + axis] = lo;
        upper[3 * j + axis] = hi;
        lowerHalfTangent[3 * j + axis] = Math.tan(lo / 2);
        upperHalfTangent[3 * j + axis] = Math.tan(hi / 2);
    }

    /**
     * A universal joint: its first axis fixed in the parent, its second in the child; its angles
     * the DOFs {@code dof} and {@code dof + 1}, stopped at [lo1, hi1] and [lo2, hi2].
     */
    public int addUniversal(int parent, int child, double[] anchorInParent, double[] anchorInChild, double[] axis1InParent,
            double[] axis2InChild, int dof, double lo1, double hi1, double lo2, double hi2) {
        int j = add(UNIVERSAL, parent, child, dof);
        System.arraycopy(anchorInParent, 0, anchor1, 3 * j, 3);
        System.arraycopy(anchorInChild, 0, anchor2, 3 * j, 3);
        System.arraycopy(axis1InParent, 0, axis1, 3 * j, 3);
        System.arraycopy(axis2InChild, 0, axis2, 3 * j, 3);
        setStop(j, 0, lo1, hi1);
        setStop(j, 1, lo2, hi2);
        // at rest both bodies are unrotated: the body-frame axes are the world axes
        if (!JointAngles.crossFrame(axis1InParent[0], axis1InParent[1], axis1InParent[2], axis2InChild[0], axis2InChild[1],
                axis2InChild[2], crossAtRest, 8 * j)
                || !JointAngles.crossFrame(axis2InChild[0], axis2InChild[1], axis2InChild[2], axis1InParent[0],
                        axis1InParent[1], axis1InParent[2], crossAtRest, 8 * j + 4)) {
            throw new IllegalArgumentException("a universal joint's axes must not be parallel");
        }
        return j;
    }

    /**
     * The stops of a ball joint's three Euler angles, the DOFs {@code dof} to {@code dof + 2}:
     * about each angle's current world axis, negated (the engine's), at [lo[i], hi[i]].
     */
    public int addEulerLimits(int parent, int child, int dof, double[] lo, double[] hi) {
        int j = add(EULER_LIMITS, parent, child, dof);
        System.arraycopy(lo, 0, lower, 3 * j, 3);
        System.arraycopy(hi, 0, upper, 3 * j, 3);
        return j;
    }

    public int count() {
        return count;
    }

    private int add(int kind, int b1, int b2, int dof) {
        if (b1 < 0 || b2 < 0 || b1 == b2) {
            throw new IllegalArgumentException("a joint needs two different bodies, got " + b1 + " and " + b2);
        }
        if (count == type.length) {
            int n = 2 * count;
            type = Arrays.copyOf(type, n);
            body1 = Arrays.copyOf(body1, n);
            body2 = Arrays.copyOf(body2, n);
            firstDof = Arrays.copyOf(firstDof, n);
            anchor1 = Arrays.copyOf(anchor1, 3 * n);
            anchor2 = Arrays.copyOf(anchor2, 3 * n);
            axis1 = Arrays.copyOf(axis1, 3 * n);
            axis2 = Arrays.copyOf(axis2, 3 * n);
            lower = Arrays.copyOf(lower, 3 * n);
            upper = Arrays.copyOf(upper, 3 * n);
            lowerHalfTangent = Arrays.copyOf(lowerHalfTangent, 3 * n);
            upperHalfTangent = Arrays.copyOf(upperHalfTangent, 3 * n);
            crossAtRest = Arrays.copyOf(crossAtRest, 8 * n);
        }
        int j = count++;
        type[j] = kind;
        body1[j] = b1;
        body2[j] = b2;
        firstDof[j] = dof;
        return j;
    }

    /** The most rows joint {@code j} can have: ball 3, its limits 3, hinge 6, universal 6. */
    int maxRows(int j) {
        return type[j] == BALL || type[j] == EULER_LIMITS ? 3 : 6;
    }
}
