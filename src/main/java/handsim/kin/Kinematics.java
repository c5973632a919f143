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

    private final HandModel model;

    public Kinematics(HandModel model) {
        this.model = model;
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
        int first = j.firstDof();
        Vec3 a0 = axis(first);
        switch (j.type()) {
            case HINGE -> {
                // twist angle about a0: 2 atan2(v . a, w)
                double s = relative.x() * a0.x() + relative.y() * a0.y() + relative.z() * a0.z();
                q[first] = wrap(2 * Math.atan2(s, relative.w()));
            }
            case UNIVERSAL -> {
                // R = R(a0, q0) R(a1, q1): in the basis (a0, a1, a0 x a1) this is Rx(q0) Ry(q1)
                Vec3 a1 = axis(first + 1);
                double[] m = inBasis(relative, a0, a1, a0.cross(a1));
                q[first] = Math.atan2(m[7], m[4]);
                q[first + 1] = Math.atan2(m[2], m[0]);
            }
            case BALL -> {
                // R = R(a0, q0) R(a1, q1) R(a2, q2): in the basis (a0, a1, s a2) with s making it
                // right-handed this is Rx(q0) Ry(q1) Rz(s q2)
                Vec3 a1 = axis(first + 1), a2 = axis(first + 2);
                double sign = Math.signum(a0.cross(a1).dot(a2));
                double[] m = inBasis(relative, a0, a1, a2.times(sign));
                q[first] = Math.atan2(-m[5], m[8]);
                q[first + 1] = Math.asin(Math.max(-1, Math.min(1, m[2])));
                q[first + 2] = sign * Math.atan2(-m[1], m[0]);
            }
        }
    }

    /**
     * Joint angle rates from the child's angular velocity relative to the parent, {@code omega}
     * expressed in the parent frame: solves {@code omega = sum_i qd_i w_i} for the current axes
     * {@code w_i} (exactly for hinges and universal joints, by Cramer's rule for ball joints).
     */
    public void rates(Joint j, double[] q, Vec3 omega, double[] qd) {
        int first = j.firstDof();
        Vec3 w0 = axis(first);
        if (j.type() == JointType.HINGE) {
            qd[first] = omega.dot(w0);
            return;
        }
        Quat r0 = Quat.fromAxisAngle(w0, q[first]);
        Vec3 w1 = r0.rotate(axis(first + 1));
        if (j.type() == JointType.UNIVERSAL) {
            // w0 and w1 stay perpendicular for a Cardan joint
            qd[first] = omega.dot(w0);
            qd[first + 1] = omega.dot(w1);
            return;
        }
        Vec3 w2 = r0.mul(Quat.fromAxisAngle(axis(first + 1), q[first + 1])).rotate(axis(first + 2));
        double det = w0.dot(w1.cross(w2));
        qd[first] = omega.dot(w1.cross(w2)) / det;
        qd[first + 1] = w0.dot(omega.cross(w2)) / det;
        qd[first + 2] = w0.dot(w1.cross(omega)) / det;
    }

    /**
     * World axes of joint {@code j}'s DOFs for angles {@code q}, given the parent's world
     * rotation: {@code w_i = R_parent R(a0, q0) ... R(a_{i-1}, q_{i-1}) a_i}. A torque
     * {@code tau_i w_i} is the generalized force of DOF i.
     */
    public Vec3[] worldAxes(Joint j, Quat parentRotation, double[] q) {
        Vec3[] out = new Vec3[j.dofCount()];
        Quat r = parentRotation;
        for (int s = 0; s < j.dofCount(); s++) {
            Dof d = model.dofs().get(j.firstDof() + s);
            out[s] = r.rotate(d.axis());
            r = r.mul(Quat.fromAxisAngle(d.axis(), q[d.index()]));
        }
        return out;
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

    /** Row-major 3x3 matrix of rotation {@code r} expressed in the orthonormal basis (b0, b1, b2). */
    private static double[] inBasis(Quat r, Vec3 b0, Vec3 b1, Vec3 b2) {
        Vec3[] b = {b0, b1, b2};
        double[] m = new double[9];
        for (int col = 0; col < 3; col++) {
            Vec3 img = r.rotate(b[col]);
            for (int row = 0; row < 3; row++) {
                m[row * 3 + col] = b[row].dot(img);
            }
        }
        return m;
    }

    /** Wraps an angle into (-pi, pi]. */
    public static double wrap(double a) {
        double w = Math.IEEEremainder(a, 2 * Math.PI);
        return w <= -Math.PI ? w + 2 * Math.PI : w;
    }
}
