package handsim.control;

import handsim.math.Vec3;
import handsim.sim.RigidState;

/**
 * The nominal controller's explicit state: FSM phase and the time it began, the current palm
 * trajectory, the hand-pose transition, the IK solution the next tick warm-starts from, and the
 * joint targets it produced. Mutable; {@link #copy()} gives an independent snapshot.
 */
public final class ControllerState {

    Phase phase;
    double phaseStart;
    PalmTrajectory trajectory;
    /** Simulated time at which {@link #trajectory} begins (the phase start, or a re-plan). */
    double trajectoryStart;
    CatchPlanner.Plan plan;
    /** The object's state the current catch was planned from, and when. */
    RigidState plannedFrom;
    double plannedAt;
    /** Simulated time at which the planned interception ends CATCH. */
    double catchEnd;
    ThrowParameters currentThrow;
    /**
     * How the current or coming catch meets the object: the throw-in's as the controller was
     * started, each later one as chosen when its THROW began; null: the controller's own way.
     */
    CatchStyle catchStyle;
    /**
     * The object's long axis at the last tick, and its turns since it last touched the hand,
     * summed as rotation vectors ({@link handsim.math.EndOverEnd#step}): how far a thrown object
     * has turned so far, for a catch that waits for a turn. Null until the hand first touches it.
     */
    Vec3 objectAxis;
    Vec3 turnSinceTouch;
    /** The hand closed on a contact since the current CATCH began. */
    boolean closedOnContact;
    HandPose handPose;
    double[] poseFrom;
    double[] weightsFrom = new double[3];
    double poseStart;
    double poseDuration;
    final double[] ikSolution;
    final double[] targets;

    ControllerState(int dofs) {
        ikSolution = new double[dofs];
        targets = new double[dofs];
        poseFrom = new double[dofs];
    }

    public Phase phase() {
        return phase;
    }

    /** Simulated time at which the current phase began (s). */
    public double phaseStart() {
        return phaseStart;
    }

    public PalmTrajectory trajectory() {
        return trajectory;
    }

    /** The plan of the current or last CATCH. */
    public CatchPlanner.Plan plan() {
        return plan;
    }

    /** The parameters of the current or last THROW (null before the first). */
    public ThrowParameters currentThrow() {
        return currentThrow;
    }

    public boolean closedOnContact() {
        return closedOnContact;
    }

    /** The hand pose the fingers are moving toward. */
    public HandPose handPose() {
        return handPose;
    }

    /** PD targets for every DOF (rad); a live view, copy what you keep. */
    public double[] targets() {
        return targets;
    }

    /** Weights of the (neutral, open, closed) poses in the current finger targets, summing to 1. */
    public double[] poseWeights(double time) {
        double s = poseDuration > 0 ? Math.max(0, Math.min(1, (time - poseStart) / poseDuration)) : 1;
        double[] w = new double[3];
        for (int i = 0; i < 3; i++) {
            w[i] = (1 - s) * weightsFrom[i] + (i == handPose.ordinal() ? s : 0);
        }
        return w;
    }

    public ControllerState copy() {
        ControllerState c = new ControllerState(targets.length);
        c.phase = phase;
        c.phaseStart = phaseStart;
        c.trajectory = trajectory;
        c.trajectoryStart = trajectoryStart;
        c.plan = plan;
        c.plannedFrom = plannedFrom;
        c.plannedAt = plannedAt;
        c.catchEnd = catchEnd;
        c.currentThrow = currentThrow;
        c.catchStyle = catchStyle;
        c.objectAxis = objectAxis;
        c.turnSinceTouch = turnSinceTouch;
        c.closedOnContact = closedOnContact;
        c.handPose = handPose;
        c.poseFrom = poseFrom.clone();
        c.weightsFrom = weightsFrom.clone();
        c.poseStart = poseStart;
        c.poseDuration = poseDuration;
        System.arraycopy(ikSolution, 0, c.ikSolution, 0, ikSolution.length);
        System.arraycopy(targets, 0, c.targets, 0, targets.length);
        return c;
    }
}
