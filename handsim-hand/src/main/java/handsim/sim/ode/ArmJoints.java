package handsim.sim.ode;

import handsim.kin.Kinematics;
import handsim.kin.Rotations;
import handsim.model.Body;
import handsim.model.HandModel;
import handsim.model.Joint;
import org.ode4j.math.DQuaternionC;
import org.ode4j.math.DVector3;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DAMotorJoint;
import org.ode4j.ode.DBody;


/**
 * The arm's joint state in the engine, read back every step: joint angles and rates from the
 * bodies' orientations and angular velocities (the decomposition of {@link Kinematics}), each
 * DOF's world axis, the joint torques applied about those axes (eq. 3) and the ball joints' limit
 * motors fed from them. Allocation-free.
 */
final class ArmJoints {

    private final Kinematics kin;
    private final Joint[] joints;
    /** Joint angles (rad) and rates (rad/s), model DOF order. */
    final double[] q;
    final double[] qd;
    /** Joint torques (N m) to apply at the next step. */
    final double[] tau;
    /** Parent body of each joint, -1 for the root (the fixed torso). */
    private final int[] parentOf;
    /** Each body's orientation (w, x, y, z), the torso's (identity) last. */
    final double[] rotations;
    /** Each body's angular velocity (rad/s, world), the torso's (zero) last. */
    private final double[] angularVels;
    /** Each DOF's world axis. */
    final double[] worldAxes;
    private final double[] relative = new double[4];
    private final double[] omegaWorld = new double[3];
    private final double[] omegaParent = new double[3];
    private final double[] work = new double[Kinematics.WORK];
    private final DVector3 motorAxis = new DVector3();

    ArmJoints(HandModel model, Kinematics kin) {
        this.kin = kin;
        int n = model.bodyCount();
        q = new double[model.dofCount()];
        qd = new double[model.dofCount()];
        tau = new double[model.dofCount()];
        joints = model.joints().toArray(new Joint[0]);
        parentOf = new int[model.joints().size()];
        for (Joint j : model.joints()) {
            parentOf[j.index()] = j.isRoot() ? -1 : j.parent();
        }
        rotations = new double[4 * (n + 1)];
        angularVels = new double[3 * (n + 1)];
        rotations[4 * n] = 1;
        worldAxes = new double[3 * model.dofCount()];
    }

    /** Body {@code b}'s angular velocity as last read (rad/s, world), component {@code i}. */
    double angularVelocity(int b, int i) {
        return angularVels[3 * b + i];
    }

    /** eq. (3): each DOF's torque about its current world axis, equal and opposite on the two bodies. */
    void applyTorques(DBody[] bodies) {
        for (Joint j : joints) {
            double tx = 0, ty = 0, tz = 0;
            for (int s = 0; s < j.dofCount(); s++) {
                int d = j.firstDof() + s;
                double t = tau[d];
                tx += t * worldAxes[3 * d];
                ty += t * worldAxes[3 * d + 1];
                tz += t * worldAxes[3 * d + 2];
            }
            bodies[j.child()].addTorque(tx, ty, tz);
            if (!j.isRoot()) {
                bodies[j.parent()].addTorque(-tx, -ty, -tz);
            }
        }
    }

    /** Feeds the ball joints' limit motors the current Euler axes (negated, see createJoint) and angles. */
    void updateLimitMotors(DAMotorJoint[] limitMotors) {
        for (Joint j : joints) {
            DAMotorJoint m = limitMotors[j.index()];
            if (m == null) {
                continue;
            }
            for (int s = 0; s < 3; s++) {
                int d = j.firstDof() + s;
                // ode4j copies the axis; its (x, y, z) overload would allocate a vector each call
                motorAxis.set(-worldAxes[3 * d], -worldAxes[3 * d + 1], -worldAxes[3 * d + 2]);
                m.setAxis(s, 0, motorAxis);
                m.setAngle(s, q[d]);
            }
        }
    }

    /**
     * Joint angles and rates from the bodies' orientations and angular velocities, and the DOFs'
     * world axes for the next step's torques and limit motors.
     */
    void update(DBody[] bodies) {
        int n = bodies.length;
        for (int b = 0; b < n; b++) {
            DQuaternionC r = bodies[b].getQuaternion();
            rotations[4 * b] = r.get0();
            rotations[4 * b + 1] = r.get1();
            rotations[4 * b + 2] = r.get2();
            rotations[4 * b + 3] = r.get3();
            DVector3C w = bodies[b].getAngularVel();
            angularVels[3 * b] = w.get0();
            angularVels[3 * b + 1] = w.get1();
            angularVels[3 * b + 2] = w.get2();
        }
        for (Joint j : joints) {
            int p = parentOf[j.index()] < 0 ? n : parentOf[j.index()];
            int c = j.child();
            Rotations.conjMul(rotations, 4 * p, rotations, 4 * c, relative, 0);
            kin.decompose(j, relative[0], relative[1], relative[2], relative[3], q);
            for (int i = 0; i < 3; i++) {
                omegaWorld[i] = angularVels[3 * c + i] - angularVels[3 * p + i];
            }
            Rotations.inverseRotate(rotations, 4 * p, omegaWorld, 0, omegaParent, 0);
            kin.rates(j, q, omegaParent[0], omegaParent[1], omegaParent[2], qd, work);
            kin.worldAxes(j, rotations, 4 * p, q, worldAxes, 3 * j.firstDof());
        }
    }
}
