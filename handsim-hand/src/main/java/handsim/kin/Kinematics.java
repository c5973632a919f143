package handsim.kin;

import handsim.math.ArcTangent;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.Body;
import handsim.model.Dof;
import handsim.model.HandModel;
import handsim.model.Joint;
import handsim.model.JointType;
import handsim.model.Site;
import java.util.List;

/**
 * Kinematics of a {@link HandModel}. A joint's rotation is the intrinsic product of its DOF
 * rotations, {@code R = R(a0, q0) R(a1, q1) R(a2, q2)}, with the axes {@code ai} given in the
 * parent frame of the zero configuration; a body's frame is its parent's frame moved to the
 * joint anchor and rotated by the joint rotation.
 */
public final class Kinematics {

    /** Size of the scratch buffer the allocation-free methods take. */
    public static final int WORK = 6;

    private final HandModel model;
    /** Unit axis of every DOF in its parent frame, 3 per DOF. */
    private final double[] axes;
    /** Per joint: the basis its rotation is decomposed in (b0, b1, b2; 9 values), null for hinges. */
    private final double[][] bases;
    /** Per ball joint: the sign s making (a0, a1, s a2) right-handed. */
    private final double[] ballSign;
    /** Per body: its origin relative to its parent's origin in the zero configuration (3 per body). */
    private final double[] offsets;
    /** Per body: the bodies from the root down to it. */
    private final int[][] chains;

    public Kinematics(HandModel model) {
        this.model = model;
        axes = new double[3 * model.dofCount()];
        for (Dof d : model.dofs()) {
            d.axis().into(axes, 3 * d.index());
        }
        offsets = new double[3 * model.bodyCount()];
        chains = new int[model.bodyCount()][];
        for (Body b : model.bodies()) {
            Vec3 parentOrigin = b.parent() < 0 ? Vec3.ZERO : model.bodies().get(b.parent()).origin();
            b.origin().minus(parentOrigin).into(offsets, 3 * b.index());
            List<Joint> chain = model.chainTo(b.index());
            chains[b.index()] = chain.stream().mapToInt(Joint::child).toArray();
        }
        bases = new double[model.joints().size()][];
        ballSign = new double[model.joints().size()];
        for (Joint j : model.joints()) {
            int first = j.firstDof();
            Vec3 a0 = axis(first);
            if (j.type() == JointType.UNIVERSAL) {
                Vec3 a1 = axis(first + 1);
                bases[j.index()] = basis(a0, a1, a0.cross(a1));
            } else if (j.type() == JointType.BALL) {
                Vec3 a1 = axis(first + 1), a2 = axis(first + 2);
                double sign = Math.signum(a0.cross(a1).dot(a2));
                ballSign[j.index()] = sign;
                bases[j.index()] = basis(a0, a1, a2.times(sign));
            }
        }
    }

    private static double[] basis(Vec3 b0, Vec3 b1, Vec3 b2) {
        double[] b = new double[9];
        b0.into(b, 0);
        b1.into(b, 3);
        b2.into(b, 6);
        return b;
    }

    public HandModel model() {
        return model;
    }

    /** Rotation of joint {@code j} (child frame relative to parent frame) for angles {@code q}. */
    public Quat jointRotation(Joint j, double[] q) {
        Quat r = Quat.IDENTITY;
        for (int s = 0; s < j.dofCount(); s++) {
            Dof d = model.dofs().get(j.firstDof() + s);
            r = r.mul(Quat.fromAxisAngle(d.axis(), q[d.index()]));
        }
        return r;
    }

    /** World frames of all bodies for joint angles {@code q}. */
    public Frame[] forward(double[] q) {
        List<Body> bodies = model.bodies();
        Frame[] frames = new Frame[bodies.size()];
        for (Body b : bodies) {
            frames[b.index()] = frameFromParent(b, b.parent() < 0 ? Frame.IDENTITY : frames[b.parent()], q);
        }
        return frames;
    }

    /** World frame of one body, computed along its chain only. */
    public Frame bodyFrame(int body, double[] q) {
        Body b = model.bodies().get(body);
        Frame parent = b.parent() < 0 ? Frame.IDENTITY : bodyFrame(b.parent(), q);
        return frameFromParent(b, parent, q);
    }

    private Frame frameFromParent(Body b, Frame parent, double[] q) {
        Joint j = model.joints().get(b.joint());
        Vec3 parentOrigin = b.parent() < 0 ? Vec3.ZERO : model.bodies().get(b.parent()).origin();
        Vec3 offset = b.origin().minus(parentOrigin);
        return new Frame(parent.pointToWorld(offset), parent.rotation().mul(jointRotation(j, q)));
    }

    /** World frame of a site. */
    public Frame siteFrame(Site site, double[] q) {
        double[] t = new double[FRAME_WORK];
        siteFrameInto(site, q, t);
        return new Frame(new Vec3(t[0], t[1], t[2]), new Quat(t[3], t[4], t[5], t[6]));
    }

    /** Size of the work buffer of {@link #siteFrameInto} and {@link #siteJacobian(Site, double[], int[], double[], double[])}. */
    public static final int SITE_WORK = 72;
    /** The part of the work buffer {@link #siteFrameInto} uses. */
    private static final int FRAME_WORK = 32;

    /**
     * The site's world frame into {@code t[0..6]} (origin, then rotation w, x, y, z), computed
     * as {@link #bodyFrame} and {@link Frame#compose} do, operation for operation, without
     * allocating; {@code t} is caller-owned work of {@link #SITE_WORK} values (32 suffice; its
     * first 7 are the result).
     */
    public void siteFrameInto(Site site, double[] q, double[] t) {
        // body frame at t[7..13], from the identity down the chain
        identityFrame(t, 7);
        for (int b : chains[site.body()]) {
            advance(b, q, t, 7, t, 14);
        }
        // compose with the site's fixed frame
        site.position().into(t, 14);
        Rotations.rotate(t, 10, t, 14, t, 17);
        t[0] = t[7] + t[17];
        t[1] = t[8] + t[18];
        t[2] = t[9] + t[19];
        Quat so = site.orientation();
        t[14] = so.w();
        t[15] = so.x();
        t[16] = so.y();
        t[17] = so.z();
        Rotations.mul(t, 10, t, 14, t, 3);
    }

    private static void identityFrame(double[] f, int o) {
        f[o] = 0;
        f[o + 1] = 0;
        f[o + 2] = 0;
        f[o + 3] = 1;
        f[o + 4] = 0;
        f[o + 5] = 0;
        f[o + 6] = 0;
    }

    /**
     * Moves the frame {@code f[o..o+6]} (a body's parent frame) to body {@code b}'s frame, as
     * {@code frameFromParent} does; uses {@code t[k..k+14]}.
     */
    private void advance(int b, double[] q, double[] f, int o, double[] t, int k) {
        // origin: parent origin + parent rotation applied to the offset
        Rotations.rotate(f, o + 3, offsets, 3 * b, t, k);
        t[k] = f[o] + t[k];
        t[k + 1] = f[o + 1] + t[k + 1];
        t[k + 2] = f[o + 2] + t[k + 2];
        // joint rotation R(a0, q0) R(a1, q1) ..., from the identity
        t[k + 3] = 1;
        t[k + 4] = 0;
        t[k + 5] = 0;
        t[k + 6] = 0;
        Joint j = model.joints().get(model.bodies().get(b).joint());
        for (int s = 0; s < j.dofCount(); s++) {
            int d = j.firstDof() + s;
            Rotations.fromAxisAngle(axes, 3 * d, q[d], t, k + 7);
            Rotations.mul(t, k + 3, t, k + 7, t, k + 11);
            System.arraycopy(t, k + 11, t, k + 3, 4);
        }
        Rotations.mul(f, o + 3, t, k + 3, t, k + 7);
        System.arraycopy(t, k + 7, f, o + 3, 4);
        System.arraycopy(t, k, f, o, 3);
    }

    /**
     * Decomposes a joint's relative rotation (child frame relative to parent frame) into its DOF
     * angles, written into {@code q} at the joint's DOF indices. Exact for rotations the joint
     * can produce; for others (constraint drift) it returns the nearest Euler angles.
     */
    public void decompose(Joint j, Quat relative, double[] q) {
        decompose(j, relative.w(), relative.x(), relative.y(), relative.z(), q);
    }

    /** {@link #decompose(Joint, Quat, double[])} for the relative rotation (w, x, y, z), without allocating. */
    public void decompose(Joint j, double w, double x, double y, double z, double[] q) {
        int first = j.firstDof();
        switch (j.type()) {
            case HINGE -> {
                // twist angle about a0: 2 atan2(v . a, w)
                int a = 3 * first;
                double s = x * axes[a] + y * axes[a + 1] + z * axes[a + 2];
                q[first] = wrap(2 * ArcTangent.atan2(s, w));
            }
            case UNIVERSAL -> {
                // R = R(a0, q0) R(a1, q1): in the basis (a0, a1, a0 x a1) this is Rx(q0) Ry(q1)
                double[] b = bases[j.index()];
                q[first] = ArcTangent.atan2(inBasis(w, x, y, z, b, 2, 1), inBasis(w, x, y, z, b, 1, 1));
                q[first + 1] = ArcTangent.atan2(inBasis(w, x, y, z, b, 0, 2), inBasis(w, x, y, z, b, 0, 0));
            }
            case BALL -> {
                // R = R(a0, q0) R(a1, q1) R(a2, q2): in the basis (a0, a1, s a2) with s making it
                // right-handed this is Rx(q0) Ry(q1) Rz(s q2)
                double[] b = bases[j.index()];
                double sign = ballSign[j.index()];
                q[first] = ArcTangent.atan2(-inBasis(w, x, y, z, b, 1, 2), inBasis(w, x, y, z, b, 2, 2));
                q[first + 1] = Math.asin(Math.max(-1, Math.min(1, inBasis(w, x, y, z, b, 0, 2))));
                q[first + 2] = sign * ArcTangent.atan2(-inBasis(w, x, y, z, b, 0, 1), inBasis(w, x, y, z, b, 0, 0));
            }
        }
    }

    /**
     * Joint angle rates from the child's angular velocity relative to the parent, {@code omega}
     * expressed in the parent frame: solves {@code omega = sum_i qd_i w_i} for the current axes
     * {@code w_i} (exactly for hinges and universal joints, by Cramer's rule for ball joints).
     */
    public void rates(Joint j, double[] q, Vec3 omega, double[] qd) {
        rates(j, q, omega.x(), omega.y(), omega.z(), qd, new double[WORK]);
    }

    /**
     * {@link #rates(Joint, double[], Vec3, double[])} for omega = (ox, oy, oz), without
     * allocating: {@code work} is caller-owned scratch of {@link #WORK} values.
     */
    public void rates(Joint j, double[] q, double ox, double oy, double oz, double[] qd, double[] work) {
        int first = j.firstDof();
        int a0 = 3 * first;
        double w0x = axes[a0], w0y = axes[a0 + 1], w0z = axes[a0 + 2];
        // omega . w0
        double dot0 = ox * w0x + oy * w0y + oz * w0z;
        if (j.type() == JointType.HINGE) {
            qd[first] = dot0;
            return;
        }
        // w1 = R(a0, q0) a1
        double h0 = 0.5 * q[first], s0 = Math.sin(h0);
        double r0w = Math.cos(h0), r0x = w0x * s0, r0y = w0y * s0, r0z = w0z * s0;
        int a1 = a0 + 3;
        Rotations.rotate(r0w, r0x, r0y, r0z, axes, a1, work, 0);
        double w1x = work[0], w1y = work[1], w1z = work[2];
        if (j.type() == JointType.UNIVERSAL) {
            // w0 and w1 stay perpendicular for a Cardan joint
            qd[first] = dot0;
            qd[first + 1] = ox * w1x + oy * w1y + oz * w1z;
            return;
        }
        // w2 = R(a0, q0) R(a1, q1) a2
        double h1 = 0.5 * q[first + 1], s1 = Math.sin(h1);
        double fw = Math.cos(h1), fx = axes[a1] * s1, fy = axes[a1 + 1] * s1, fz = axes[a1 + 2] * s1;
        double rw = r0w * fw - r0x * fx - r0y * fy - r0z * fz;
        double rx = r0w * fx + r0x * fw + r0y * fz - r0z * fy;
        double ry = r0w * fy - r0x * fz + r0y * fw + r0z * fx;
        double rz = r0w * fz + r0x * fy - r0y * fx + r0z * fw;
        int a2 = a1 + 3;
        Rotations.rotate(rw, rx, ry, rz, axes, a2, work, 3);
        double w2x = work[3], w2y = work[4], w2z = work[5];
        // Cramer's rule on omega = qd0 w0 + qd1 w1 + qd2 w2
        double cx = w1y * w2z - w1z * w2y, cy = w1z * w2x - w1x * w2z, cz = w1x * w2y - w1y * w2x;
        double det = w0x * cx + w0y * cy + w0z * cz;
        qd[first] = (ox * cx + oy * cy + oz * cz) / det;
        double ex = oy * w2z - oz * w2y, ey = oz * w2x - ox * w2z, ez = ox * w2y - oy * w2x;
        qd[first + 1] = (w0x * ex + w0y * ey + w0z * ez) / det;
        double gx = w1y * oz - w1z * oy, gy = w1z * ox - w1x * oz, gz = w1x * oy - w1y * ox;
        qd[first + 2] = (w0x * gx + w0y * gy + w0z * gz) / det;
    }

    /**
     * World axes of joint {@code j}'s DOFs for angles {@code q}, given the parent's world
     * rotation: {@code w_i = R_parent R(a0, q0) ... R(a_{i-1}, q_{i-1}) a_i}. A torque
     * {@code tau_i w_i} is the generalized force of DOF i.
     */
    public Vec3[] worldAxes(Joint j, Quat parentRotation, double[] q) {
        double[] p = {parentRotation.w(), parentRotation.x(), parentRotation.y(), parentRotation.z()};
        double[] w = new double[3 * j.dofCount()];
        worldAxes(j, p, 0, q, w, 0);
        Vec3[] out = new Vec3[j.dofCount()];
        for (int s = 0; s < out.length; s++) {
            out[s] = Vec3.of(w, 3 * s);
        }
        return out;
    }

    /**
     * {@link #worldAxes(Joint, Quat, double[])} without allocating: the parent's world rotation
     * is {@code parent[p..p+3]} (w, x, y, z) and the axis of the joint's DOF s is written to
     * {@code out[o + 3 s .. o + 3 s + 2]}.
     */
    public void worldAxes(Joint j, double[] parent, int p, double[] q, double[] out, int o) {
        double rw = parent[p], rx = parent[p + 1], ry = parent[p + 2], rz = parent[p + 3];
        int n = j.dofCount();
        for (int s = 0; s < n; s++) {
            int d = j.firstDof() + s;
            Rotations.rotate(rw, rx, ry, rz, axes, 3 * d, out, o + 3 * s);
            if (s + 1 < n) {
                // r = r R(a_s, q_s)
                double h = 0.5 * q[d], sn = Math.sin(h);
                double fw = Math.cos(h), fx = axes[3 * d] * sn, fy = axes[3 * d + 1] * sn, fz = axes[3 * d + 2] * sn;
                double nw = rw * fw - rx * fx - ry * fy - rz * fz;
                double nx = rw * fx + rx * fw + ry * fz - rz * fy;
                double ny = rw * fy - rx * fz + ry * fw + rz * fx;
                double nz = rw * fz + rx * fy - ry * fx + rz * fw;
                rw = nw;
                rx = nx;
                ry = ny;
                rz = nz;
            }
        }
    }

    /**
     * Jacobian of a site's position (rows 0-2) and orientation (rows 3-5, angular velocity) with
     * respect to the listed DOFs ({@code dofs}, which should lie on the site's chain; others give
     * zero columns). {@code jac} is row-major 6 x dofs.length.
     */
    public void siteJacobian(Site site, double[] q, int[] dofs, double[] jac) {
        siteJacobian(site, q, dofs, jac, new double[SITE_WORK]);
    }

    /** {@link #siteJacobian(Site, double[], int[], double[])} without allocating: {@code t} is work of {@link #SITE_WORK} values. */
    public void siteJacobian(Site site, double[] q, int[] dofs, double[] jac, double[] t) {
        java.util.Arrays.fill(jac, 0);
        // the site's origin p at t[0..2]
        siteFrameInto(site, q, t);
        int n = dofs.length;
        // the parent frame of each joint on the chain at F = t[32..38]; scratch from t[39]
        final int f = 32, anchor = f + 7, axesAt = f + 10, tmp = f + 19;
        identityFrame(t, f);
        for (int b : chains[site.body()]) {
            Joint j = model.joints().get(model.bodies().get(b).joint());
            if (j.isRoot()) {
                j.anchor().into(t, anchor);
            } else {
                Rotations.rotate(t, f + 3, offsets, 3 * b, t, tmp);
                t[anchor] = t[f] + t[tmp];
                t[anchor + 1] = t[f + 1] + t[tmp + 1];
                t[anchor + 2] = t[f + 2] + t[tmp + 2];
            }
            worldAxes(j, t, f + 3, q, t, axesAt);
            for (int s = 0; s < j.dofCount(); s++) {
                int col = indexOf(dofs, j.firstDof() + s);
                if (col < 0) {
                    continue;
                }
                // linear part: w x (p - anchor)
                int w = axesAt + 3 * s;
                t[tmp] = t[0] - t[anchor];
                t[tmp + 1] = t[1] - t[anchor + 1];
                t[tmp + 2] = t[2] - t[anchor + 2];
                Rotations.cross(t, w, t, tmp, t, tmp + 3);
                jac[col] = t[tmp + 3];
                jac[n + col] = t[tmp + 4];
                jac[2 * n + col] = t[tmp + 5];
                jac[3 * n + col] = t[w];
                jac[4 * n + col] = t[w + 1];
                jac[5 * n + col] = t[w + 2];
            }
            advance(b, q, t, f, t, tmp);
        }
    }

    private static int indexOf(int[] a, int v) {
        for (int i = 0; i < a.length; i++) {
            if (a[i] == v) {
                return i;
            }
        }
        return -1;
    }

    private Vec3 axis(int dof) {
        return model.dofs().get(dof).axis();
    }

    /**
     * Entry (row, col) of the rotation (w, x, y, z) expressed in the orthonormal basis {@code b}
     * (b0, b1, b2 in a row): {@code b_row . R b_col}.
     */
    private static double inBasis(double w, double x, double y, double z, double[] b, int row, int col) {
        return Rotations.rotateDot(w, x, y, z, b, 3 * col, b, 3 * row);
    }

    /** Wraps an angle into (-pi, pi]. */
    public static double wrap(double a) {
        double w = remainder(a);
        return w <= -Math.PI ? w + 2 * Math.PI : w;
    }

    /**
     * Math.IEEEremainder(a, 2 pi), bit for bit, without its native call where |a| <= 2 pi (a
     * hinge's 2 atan2): the quotient then rounds to 0 up to |a| = pi (a tie rounds to even) and
     * to +-1 beyond it, where a -+ 2 pi is exact (Sterbenz), an exact zero taking a's sign as the
     * IEEE remainder does.
     */
    static double remainder(double a) {
        double p = 2 * Math.PI;
        double m = Math.abs(a);
        if (m <= Math.PI) {
            return a;
        }
        if (m <= p) {
            double r = a > 0 ? a - p : a + p;
            return r == 0 ? 0 * a : r;
        }
        return Math.IEEEremainder(a, p);
    }
}
