package handsim.control;

import handsim.model.Dof;
import handsim.model.HandModel;

/**
 * Joint-space PD control of every DOF (eq. 3): {@code tau = kp (target - q) - kd qd}, clamped
 * to the DOF's human strength. The printed eq. (3) adds {@code + kd qd}; damping must oppose the
 * velocity, so the sign here is minus. Gains per DOF come from eq. (4) with the mass driven by
 * the DOF's joint.
 */
public final class PdController {

    private final HandModel model;
    private final double[] kp;
    private final double[] kd;

    public PdController(HandModel model, PdGains gains) {
        this.model = model;
        int n = model.dofCount();
        kp = new double[n];
        kd = new double[n];
        for (Dof d : model.dofs()) {
            double m = model.drivenMass(d.joint());
            kp[d.index()] = gains.kp(m);
            kd[d.index()] = gains.kd(m);
        }
    }

    public double kp(int dof) {
        return kp[dof];
    }

    public double kd(int dof) {
        return kd[dof];
    }

    /**
     * Writes the clamped torques for joint angles {@code q}, rates {@code qd} and targets
     * {@code target} into {@code tau}; all arrays are in the model's DOF order.
     */
    public void torques(double[] q, double[] qd, double[] target, double[] tau) {
        for (int i = 0; i < tau.length; i++) {
            double t = kp[i] * (target[i] - q[i]) - kd[i] * qd[i];
            tau[i] = model.dofs().get(i).clampTorque(t);
        }
    }
}
