package handsim.task;

import handsim.control.PdController;
import handsim.model.Dof;
import handsim.sim.Simulator;

/**
 * The step order of every run, in one place: read the joints, compute the PD torques of eq. (3)
 * toward the current targets, add each joint's passive viscous torque, apply them, take one
 * physics step. The controller writes
 * {@link #targets()} at its own rate, a whole number of physics steps.
 */
public final class ServoLoop {

    private final Simulator sim;
    private final PdController pd;
    private final double[] q;
    private final double[] qd;
    private final double[] tau;
    private final double[] targets;

    public ServoLoop(Simulator sim, PdController pd) {
        this.sim = sim;
        this.pd = pd;
        int n = sim.model().dofCount();
        q = new double[n];
        qd = new double[n];
        tau = new double[n];
        targets = new double[n];
    }

    public Simulator sim() {
        return sim;
    }

    /** The joint-angle targets (rad, model DOF order) the PD tracks; write into it. */
    public double[] targets() {
        return targets;
    }

    /**
     * One physics step with PD torques toward {@link #targets()}; returns the step's largest
     * |PD torque| / strength limit over the joints (1 = at the limit).
     */
    public double step() {
        sim.readJoints(q, qd);
        pd.torques(q, qd, targets, tau);
        double peakTorqueRatio = 0;
        for (int i = 0; i < tau.length; i++) {
            Dof d = sim.model().dofs().get(i);
            peakTorqueRatio = Math.max(peakTorqueRatio, d.torqueRatio(tau[i]));
            tau[i] -= d.passiveDamping() * qd[i];
        }
        sim.setJointTorques(tau);
        sim.step();
        return peakTorqueRatio;
    }

    /** Advances by {@code steps} physics steps. */
    public void step(int steps) {
        for (int i = 0; i < steps; i++) {
            step();
        }
    }
}
