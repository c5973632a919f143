package handsim.sim.island;

import static handsim.sim.island.ConstraintRows.CFM;
import static handsim.sim.island.ConstraintRows.HI;
import static handsim.sim.island.ConstraintRows.J1;
import static handsim.sim.island.ConstraintRows.J2;
import static handsim.sim.island.ConstraintRows.LO;
import static handsim.sim.island.ConstraintRows.RHS;

/**
 * The constraint rows of the articulation's joints and of contacts, formulated as ODE
 * formulates them (rhs and cfm here as ODE's joints state them, per step of 1/fps seconds;
 * {@link IslandStep} turns them into rates):
 * <ul>
 * <li>ball: three rows holding the two anchors together, the error fed back at ERP;
 * <li>hinge: the ball rows and two rows keeping the bodies' angular velocities equal across the
 * axis (about the plane space p, q of the parent's axis), the axes' misalignment ax1 x ax2 fed
 * back along p and q; a stop row when the angle passes a limit;
 * <li>universal: the ball rows and a row keeping the two axes perpendicular (about p, the unit
 * normal of both), the error cos(angle) = ax1 . ax2; a stop row per axis at its limit;
 * <li>Euler limits of a ball joint: a stop row about each Euler angle's axis at its limit;
 * <li>contact: a normal row pushing the depth out at the contact's ERP, compliant by its CFM,
 * impulse in [0, inf); two friction rows along the normal's plane space, their impulse bounded
 * by mu times the normal's (ODE's approximation 1 of the Coulomb cone).
 * </ul>
 * A stop row turns the body pair about the axis: rhs -fps erp (angle - stop), bounded to push
 * away from the stop only.
 */
final class RowAssembly {

    private final double[] s = new double[24];
    private final double[] q = new double[16];
    private final double[] rotation = new double[4];

    /** World-level ERP and CFM of the joints (ODE's world defaults), and of their stops. */
    private final double erp;
    private final double cfm;

    RowAssembly(double erp, double cfm) {
        this.erp = erp;
        this.cfm = cfm;
    }

    /**
     * Appends joint {@code j}'s rows; {@code angles} are the DOF angles (rad) and {@code dofAxes}
     * their world axes (3 each), for the Euler angles' stops (a hinge's and a universal joint's
     * angles are measured from the bodies, {@link JointAngles}).
     */
    void joint(Articulation a, int j, RigidBodies b, ConstraintRows rows, double fps, double[] angles, double[] dofAxes) {
        switch (a.type[j]) {
            case Articulation.BALL -> ball(a, j, b, rows, fps);
            case Articulation.HINGE -> hinge(a, j, b, rows, fps);
            case Articulation.UNIVERSAL -> universal(a, j, b, rows, fps);
            default -> eulerLimits(a, j, rows, fps, angles, dofAxes);
        }
    }

    /** The three anchor rows: J1 = (1, -[a1]x), J2 = (-1, [a2]x), rhs = fps erp (p2 + a2 - p1 - a1). */
    private void ball(Articulation a, int j, RigidBodies b, ConstraintRows rows, double fps) {
        int b1 = a.body1[j], b2 = a.body2[j];
        double[] p = b.position;
        int p1 = 3 * b1, p2 = 3 * b2;
        // the anchors relative to the centres of mass, world frame: a1 = R1 anchor1, a2 = R2 anchor2
        Matrix3.multiply(b.rotation, 9 * b1, a.anchor1, 3 * j, s, 0);
        Matrix3.multiply(b.rotation, 9 * b2, a.anchor2, 3 * j, s, 3);
        double a1x = s[0], a1y = s[1], a1z = s[2], a2x = s[3], a2y = s[4], a2z = s[5];
        double k = fps * erp;
        int st = ConstraintRows.STRIDE;
        int o = rows.add(b1, b2, cfm, ConstraintRows.ANCHOR_X);
        rows.add(b1, b2, cfm, ConstraintRows.ANCHOR_Y);
        rows.add(b1, b2, cfm, ConstraintRows.ANCHOR_Z);
        double[] d = rows.data;
        d[o + J1] = 1;
        d[o + J2] = -1;
        d[o + RHS] = k * (a2x + p[p2] - a1x - p[p1]);
        d[o + st + J1 + 1] = 1;
        d[o + st + J2 + 1] = -1;
        d[o + st + RHS] = k * (a2y + p[p2 + 1] - a1y - p[p1 + 1]);
        d[o + 2 * st + J1 + 2] = 1;
        d[o + 2 * st + J2 + 2] = -1;
        d[o + 2 * st + RHS] = k * (a2z + p[p2 + 2] - a1z - p[p1 + 2]);
        // J1's angular part -[a1]x, J2's [a2]x, row by row
        d[o + J1 + 4] = a1z;
        d[o + J1 + 5] = -a1y;
        d[o + st + J1 + 3] = -a1z;
        d[o + st + J1 + 5] = a1x;
        d[o + 2 * st + J1 + 3] = a1y;
        d[o + 2 * st + J1 + 4] = -a1x;
        d[o + J2 + 4] = -a2z;
        d[o + J2 + 5] = a2y;
        d[o + st + J2 + 3] = a2z;
        d[o + st + J2 + 5] = -a2x;
        d[o + 2 * st + J2 + 3] = -a2y;
        d[o + 2 * st + J2 + 4] = a2x;
    }

    private void hinge(Articulation a, int j, RigidBodies b, ConstraintRows rows, double fps) {
        ball(a, j, b, rows, fps);
        int b1 = a.body1[j], b2 = a.body2[j];
        int x = 3 * j;
        // ax1 at s[0], p at s[3], q at s[6], ax2 at s[9], ax1 x ax2 at s[12]
        Matrix3.multiply(b.rotation, 9 * b1, a.axis1, x, s, 0);
        Matrix3.planeSpace(s[0], s[1], s[2], s, 3, 6);
        Matrix3.multiply(b.rotation, 9 * b2, a.axis2, x, s, 9);
        cross(s, 0, s, 9, s, 12);
        double k = fps * erp;
        for (int r = 0; r < 2; r++) {
            int o = rows.add(b1, b2, cfm, ConstraintRows.ANGULAR);
            double[] d = rows.data;
            int v = 3 + 3 * r;
            for (int i = 0; i < 3; i++) {
                d[o + J1 + 3 + i] = s[v + i];
                d[o + J2 + 3 + i] = -s[v + i];
            }
            d[o + RHS] = k * (s[12] * s[v] + s[13] * s[v + 1] + s[14] * s[v + 2]);
        }
        JointAngles.hinge(b.orientation, 4 * b1, b.orientation, 4 * b2, a.axis1, x, q, rotation, 0);
        rotationStop(a, x, rows, b1, b2, fps, rotation[0], rotation[1], 1, s, 0);
    }

    private void universal(Articulation a, int j, RigidBodies b, ConstraintRows rows, double fps) {
        ball(a, j, b, rows, fps);
        int b1 = a.body1[j], b2 = a.body2[j];
        // ax1 at s[0], ax2 at s[3], ax2 made perpendicular to ax1 at s[6], p at s[9]
        Matrix3.multiply(b.rotation, 9 * b1, a.axis1, 3 * j, s, 0);
        Matrix3.multiply(b.rotation, 9 * b2, a.axis2, 3 * j, s, 3);
        double k = s[0] * s[3] + s[1] * s[4] + s[2] * s[5];
        for (int i = 0; i < 3; i++) {
            s[6 + i] = s[3 + i] + -k * s[i];
        }
        cross(s, 0, s, 6, s, 9);
        double l = 1 / Math.sqrt(s[9] * s[9] + s[10] * s[10] + s[11] * s[11]);
        int o = rows.add(b1, b2, cfm, ConstraintRows.ANGULAR);
        double[] d = rows.data;
        for (int i = 0; i < 3; i++) {
            double p = s[9 + i] * l;
            d[o + J1 + 3 + i] = p;
            d[o + J2 + 3 + i] = -p;
        }
        d[o + RHS] = fps * erp * -k;
        JointAngles.universal(b.orientation, 4 * b1, b.orientation, 4 * b2, s, 0, a.crossAtRest, 8 * j, a.axis1, a.axis2, 3 * j,
                rotation, q);
        rotationStop(a, 3 * j, rows, b1, b2, fps, rotation[0], rotation[1], 1, s, 0);
        rotationStop(a, 3 * j + 1, rows, b1, b2, fps, rotation[2], rotation[3], -1, s, 3);
    }

    private void eulerLimits(Articulation a, int j, ConstraintRows rows, double fps, double[] angles, double[] dofAxes) {
        for (int i = 0; i < 3; i++) {
            int dof = a.firstDof[j] + i;
            double x = -dofAxes[3 * dof], y = -dofAxes[3 * dof + 1], z = -dofAxes[3 * dof + 2];
            double l = 1 / Math.sqrt(x * x + y * y + z * z);
            s[15] = x * l;
            s[16] = y * l;
            s[17] = z * l;
            stop(rows, a.body1[j], a.body2[j], fps, angles[dof], a.lower[3 * j + i], a.upper[3 * j + i], s, 15);
        }
    }

    /**
     * The stop {@code k} of a hinge or universal joint at the angle {@code sign} times the
     * rotation (sinHalf, cosHalf) of {@link JointAngles}: tested as ODE tests it, only when the
     * stops lie within half a turn of the zero angle, first by the half angle's tangent (which
     * orders angles as they are ordered), the angle itself taken only at a stop.
     */
    private void rotationStop(Articulation a, int k, ConstraintRows rows, int b1, int b2, double fps, double sinHalf, double cosHalf,
            double sign, double[] axis, int ai) {
        double lo = a.lower[k], hi = a.upper[k];
        if (!((lo >= -Math.PI || hi <= Math.PI) && lo <= hi)) {
            return;
        }
        double t = sign * JointAngles.halfTangent(sinHalf, cosHalf);
        double tLo = a.lowerHalfTangent[k], tHi = a.upperHalfTangent[k];
        // a relative margin of 1e-9 leaves the decision at a tie to the angle itself
        if (t <= tLo + 1e-9 * (1 + Math.abs(tLo)) || t >= tHi - 1e-9 * (1 + Math.abs(tHi))) {
            stop(rows, b1, b2, fps, sign * JointAngles.angle(sinHalf, cosHalf), lo, hi, axis, ai);
        }
    }

    /** A stop row about the unit axis at {@code ai} when {@code angle} is at or past a stop. */
    private void stop(ConstraintRows rows, int b1, int b2, double fps, double angle, double lo, double hi, double[] axis, int ai) {
        int limit;
        double error;
        if (angle <= lo) {
            limit = 1;
            error = angle - lo;
        } else if (angle >= hi) {
            limit = 2;
            error = angle - hi;
        } else {
            return;
        }
        int o = rows.add(b1, b2, cfm, ConstraintRows.ANGULAR);
        double[] d = rows.data;
        for (int i = 0; i < 3; i++) {
            d[o + J1 + 3 + i] = axis[ai + i];
            d[o + J2 + 3 + i] = -axis[ai + i];
        }
        d[o + RHS] = -(fps * erp) * error;
        d[o + CFM] = cfm;
        if (lo == hi) {
            return;
        }
        if (limit == 1) {
            d[o + LO] = 0;
        } else {
            d[o + HI] = 0;
        }
    }

    /** Appends contact {@code k}'s normal row and, with friction, its two friction rows. */
    void contact(ContactPoints c, int k, RigidBodies b, ConstraintRows rows, double fps) {
        int b1 = c.body1[k], b2 = c.body2[k];
        int g = ContactPoints.GEOMETRY * k;
        double[] cd = c.data;
        double nx = cd[g + ContactPoints.NORMAL], ny = cd[g + ContactPoints.NORMAL + 1], nz = cd[g + ContactPoints.NORMAL + 2];
        double depth = Math.max(cd[g + ContactPoints.DEPTH], 0);
        // c1 at s[0], c2 at s[3]: the point relative to each body's centre of mass
        for (int i = 0; i < 3; i++) {
            s[i] = cd[g + ContactPoints.POINT + i] - b.position[3 * b1 + i];
            s[3 + i] = b2 >= 0 ? cd[g + ContactPoints.POINT + i] - b.position[3 * b2 + i] : 0;
        }
        s[6] = nx;
        s[7] = ny;
        s[8] = nz;
        int normal = rows.count;
        frictionless(rows, b1, b2, s, 6);
        double[] d = rows.data;
        int o = ConstraintRows.STRIDE * normal;
        d[o + RHS] = fps * cd[g + ContactPoints.ERP] * depth;
        d[o + CFM] = cd[g + ContactPoints.CFM];
        d[o + LO] = 0;
        double mu = cd[g + ContactPoints.MU];
        if (!(mu > 0)) {
            return;
        }
        Matrix3.planeSpace(nx, ny, nz, s, 9, 12);
        for (int t = 9; t <= 12; t += 3) {
            int row = rows.count;
            frictionless(rows, b1, b2, s, t);
            d = rows.data;
            o = ConstraintRows.STRIDE * row;
            d[o + LO] = -mu;
            d[o + HI] = mu;
            rows.findex[row] = normal;
        }
    }

    /** A row along the unit direction at {@code di}: J1 = (u, c1 x u), J2 = (-u, u x c2). */
    private void frictionless(ConstraintRows rows, int b1, int b2, double[] v, int di) {
        int o = rows.add(b1, b2, cfm);
        double[] d = rows.data;
        for (int i = 0; i < 3; i++) {
            d[o + J1 + i] = v[di + i];
        }
        cross(v, 0, v, di, d, o + J1 + 3);
        if (b2 >= 0) {
            for (int i = 0; i < 3; i++) {
                d[o + J2 + i] = -v[di + i];
            }
            cross(v, di, v, 3, d, o + J2 + 3);
        }
    }

    /** out = a x b. */
    static void cross(double[] a, int ai, double[] b, int bi, double[] out, int oi) {
        double ax = a[ai], ay = a[ai + 1], az = a[ai + 2], bx = b[bi], by = b[bi + 1], bz = b[bi + 2];
        out[oi] = ay * bz - az * by;
        out[oi + 1] = az * bx - ax * bz;
        out[oi + 2] = ax * by - ay * bx;
    }
}
