package handsim.kin;

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

    public Kinematics(HandModel model) {
        this.model = model;
        axes = new double[3 * model.dofCount()];
        for (Dof d : model.dofs()) {
            d.axis().into(axes, 3 * d.index());
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
        return bodyFrame(site.body(), q).compose(new Frame(site.position(), site.orientation()));
    }

    /**
     * Decomposes a joint's relative rotation (child frame relative to parent frame) into its DOF
     * angles, written into {@code q} at the joint's DOF indices. Exact for rotations the joint
     * can produce; for others (constraint drift) it returns the nearest Euler angles.
     */
    public void decompose(Joint j, Quat relative, double[] q) {
        decompose(j, relative.w(), relative.x(), relative.y(), relative.z(), q, new double[WORK]);
    }

    /**
     * {@link #decompose(Joint, Quat, double[])} for the relative rotation (w, x, y, z), without
     * allocating: {@code work} is caller-owned scratch of {@link #WORK} values.
     */
    public void decompose(Joint j, double w, double x, double y, double z, double[] q, double[] work) {
        int first = j.firstDof();
        switch (j.type()) {
            case HINGE -> {
                // twist angle about a0: 2 atan2(v . a, w)
                int a = 3 * first;
                double s = x * axes[a] + y * axes[a + 1] + z * axes[a + 2];
                q[first] = wrap(2 * Math.atan2(s, w));
            }
            case UNIVERSAL -> {
                // R = R(a0, q0) R(a1, q1): in the basis (a0, a1, a0 x a1) this is Rx(q0) Ry(q1)
                double[] b = bases[j.index()];
                q[first] = Math.atan2(inBasis(w, x, y, z, b, 2, 1, work), inBasis(w, x, y, z, b, 1, 1, work));
                q[first + 1] = Math.atan2(inBasis(w, x, y, z, b, 0, 2, work), inBasis(w, x, y, z, b, 0, 0, work));
            }
            case BALL -> {
                // R = R(a0, q0) R(a1, q1) R(a2, q2): in the basis (a0, a1, s a2) with s making it
                // right-handed this is Rx(q0) Ry(q1) Rz(s q2)
                double[] b = bases[j.index()];
                double sign = ballSign[j.index()];
                q[first] = Math.atan2(-inBasis(w, x, y, z, b, 1, 2, work), inBasis(w, x, y, z, b, 2, 2, work));
                q[first + 1] = Math.asin(Math.max(-1, Math.min(1, inBasis(w, x, y, z, b, 0, 2, work))));
                q[first + 2] = sign * Math.atan2(-inBasis(w, x, y, z, b, 0, 1, work), inBasis(w, x, y, z, b, 0, 0, work));
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
        java.util.Arrays.fill(jac, 0);
        Vec3 p = siteFrame(site, q).origin();
        List<Joint> chain = model.chainTo(site.body());
        int n = dofs.length;
        Frame parent = Frame.IDENTITY;
        for (Joint j : chain) {
            Body child = model.bodies().get(j.child());
            Vec3 anchor = j.isRoot() ? j.anchor() : parent.pointToWorld(child.origin().minus(model.bodies().get(j.parent()).origin()));
            Vec3[] w = worldAxes(j, parent.rotation(), q);
            for (int s = 0; s < w.length; s++) {
                int col = indexOf(dofs, j.firstDof() + s);
                if (col < 0) {
                    continue;
                }
                Vec3 lin = w[s].cross(p.minus(anchor));
                jac[col] = lin.x();
                jac[n + col] = lin.y();
                jac[2 * n + col] = lin.z();
                jac[3 * n + col] = w[s].x();
                jac[4 * n + col] = w[s].y();
                jac[5 * n + col] = w[s].z();
            }
            parent = frameFromParent(child, parent, q);
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
    private static double inBasis(double w, double x, double y, double z, double[] b, int row, int col, double[] work) {
        Rotations.rotate(w, x, y, z, b, 3 * col, work, 0);
        return Rotations.dot(b, 3 * row, work, 0);
    }

    /** Wraps an angle into (-pi, pi]. */
    public static double wrap(double a) {
        double w = Math.IEEEremainder(a, 2 * Math.PI);
        return w <= -Math.PI ? w + 2 * Math.PI : w;
    }
}
