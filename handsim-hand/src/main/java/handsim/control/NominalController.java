package handsim.control;

import handsim.kin.Frame;
import handsim.kin.Kinematics;
import handsim.math.EndOverEnd;
import handsim.math.Hermite;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.model.Site;
import handsim.sim.ObjectSpec;
import java.util.Objects;

/**
 * The paper's nominal catch-and-throw controller (sec. 3). A finite state machine CATCH ->
 * MIDDLE -> THROW -> GOBACK -> CATCH, timed by the elapsed time in each state; each state moves
 * the palm centre along a Hermite curve (eq. 1) with SLERP rotation, tracked by damped least
 * squares IK (eq. 2); the fingers follow the neutral / open / closed poses. The hand closes at
 * the first hand-object contact since CATCH began; THROW's curve comes from the {@link
 * ThrowDecision} made when MIDDLE ends ({@link #throwDue}, {@link #beginThrow}). Engine-free: it
 * reads an {@link Observation} and its {@link ControllerState}.
 */
public final class NominalController {

    private final HandModel model;
    private final ControllerConfig config;
    private final ObjectSpec object;
    private final Kinematics kin;
    private final Site palm;
    private final DlsIk ik;
    private final Grasp grasp;
    private final HandPoses poses;
    private final Ballistics ballistics;
    private final CatchPlanner planner;
    private final double[] neutralPose;
    private final Frame neutralPalm;
    /** The config's {@link ArmRest}, or null; its posture in {@link DlsIk#dofs} order. */
    private final ArmRest armRest;
    private final double[] armRestPosture;

    /**
     * @param object the object to catch; its name selects the grasp in {@code config}
     * @param gravity world gravity, for predicting the object's flight
     */
    public NominalController(HandModel model, ControllerConfig config, ObjectSpec object, Vec3 gravity) {
        this.model = model;
        this.config = config;
        this.object = object;
        this.kin = new Kinematics(model);
        this.palm = model.site("palm_center");
        this.ik = new DlsIk(kin, palm, config.ik());
        this.grasp = config.grasps().forObject(object.name());
        try {
            this.poses = new HandPoses(kin, ik.dofs(), grasp);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("grasp of " + object.name() + " in the controller config: " + e.getMessage(), e);
        }
        this.ballistics = new Ballistics(gravity);
        this.planner = new CatchPlanner(ballistics, config.interceptionHeight(),
                config.catchVelocityFraction(), config.catchMinDuration(), config.headingSearch(), config.fallingTilt());
        this.neutralPose = model.poseVector("neutral");
        this.neutralPalm = kin.siteFrame(palm, neutralPose);
        try {
            this.armRest = config.armRest().orElse(null);
            this.armRestPosture = armRest == null ? null : armRest.chainVector(model, ik.dofs());
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("the arm rest for the " + object.name() + " (its armRest): " + e.getMessage(), e);
        }
    }

    public ControllerConfig config() {
        return config;
    }

    /** The object this controller catches (its grasp and its predicted flight are planned for it). */
    public ObjectSpec object() {
        return object;
    }

    /** The palm centre's frame in the neutral pose: where MIDDLE ends and THROW starts. */
    public Frame neutralPalm() {
        return neutralPalm;
    }

    /** A fresh state beginning in CATCH at the observation's time, planned from its object state. */
    public ControllerState start(Observation obs) {
        return start(obs, null);
    }

    /** {@link #start} with the throw-in met as {@code throwIn} says (null: the controller's own way). */
    public ControllerState start(Observation obs, CatchStyle throwIn) {
        ControllerState s = new ControllerState(model.dofCount());
        s.catchStyle = throwIn;
        System.arraycopy(obs.q(), 0, s.ikSolution, 0, s.ikSolution.length);
        System.arraycopy(obs.q(), 0, s.targets, 0, s.targets.length);
        s.handPose = HandPose.NEUTRAL;
        s.weightsFrom[HandPose.NEUTRAL.ordinal()] = 1;
        System.arraycopy(obs.q(), 0, s.poseFrom, 0, s.poseFrom.length);
        enter(Phase.CATCH, obs, s, null);
        update(obs, s);
        return s;
    }

    /**
     * While THROW or GOBACK runs, before the coming catch is planned: that catch meets the object
     * as {@code style} says. Nothing the hand does before CATCH depends on it, so a planner can
     * play one throw once and branch its catch here; a {@link ThrowDecision} that named {@code
     * style} when THROW began makes the same catch.
     */
    public void meetComingCatchAs(ControllerState s, CatchStyle style) {
        if (s.phase != Phase.THROW && s.phase != Phase.GOBACK) {
            throw new IllegalStateException("the coming catch is chosen in THROW or GOBACK, not in " + s.phase);
        }
        s.catchStyle = Objects.requireNonNull(style, "style");
    }

    /**
     * True when this observation ends MIDDLE and begins a THROW, whose parameters are then
     * decided ({@link #beginThrow}): the moment a learner decides (sec. 3.7).
     */
    public boolean throwDue(Observation obs, ControllerState s) {
        return s.phase == Phase.MIDDLE && obs.time() - s.phaseStart >= duration(s);
    }

    /**
     * Advances the state machine to the observation's time and writes the new targets. A throw
     * due at this observation ({@link #throwDue}) is begun by {@link #beginThrow} instead.
     */
    public void update(Observation obs, ControllerState s) {
        if (throwDue(obs, s)) {
            throw new IllegalStateException("a throw is due at t = " + obs.time() + " s: begin it with its decision (beginThrow)");
        }
        advance(obs, s, null);
    }

    /** At a throw's decision ({@link #throwDue}): ends MIDDLE and begins the THROW that {@code decision} says. */
    public void beginThrow(Observation obs, ControllerState s, ThrowDecision decision) {
        if (!throwDue(obs, s)) {
            throw new IllegalStateException("no throw is due in " + s.phase + " at t = " + obs.time() + " s");
        }
        advance(obs, s, Objects.requireNonNull(decision, "decision"));
    }

    /** {@link #update} and {@link #beginThrow}: {@code decision} is the throw's when one begins, else null. */
    private void advance(Observation obs, ControllerState s, ThrowDecision decision) {
        followTurn(obs, s);
        // the hand closes at the first hand-object contact since CATCH began (sec. 3.1)
        if (obs.handTouchedObject() && !s.closedOnContact && (s.phase == Phase.CATCH || s.phase == Phase.MIDDLE)) {
            s.closedOnContact = true;
            blendTo(HandPose.CLOSED, config.closeTime(), obs.time(), s);
        }
        // state transitions on the elapsed time in the state (sec. 3.1, Fig. 3), or THROW's on the object's turn
        if (stateOver(obs, s)) {
            enter(s.phase.next(), obs, s, decision);
        } else if (s.phase == Phase.CATCH && !s.closedOnContact && leftPredictedFlight(obs, s)) {
            // the object did not fly as predicted (it bounced off the box): plan the catch again
            replanCatch(obs, s);
        }
        if (s.phase == Phase.THROW && obs.time() - s.phaseStart >= s.currentThrow.tOpen() && s.handPose != HandPose.OPEN) {
            blendTo(HandPose.OPEN, config.openTime(), obs.time(), s);
        }
        // palm target along the state's curve, then IK for shoulder, elbow and wrist (eq. 2)
        double t = obs.time() - s.trajectoryStart;
        ik.solve(s.ikSolution, s.phase == Phase.THROW ? s.trajectory.continuedAt(t) : s.trajectory.at(t));
        if (armRest != null && armRest.phases().contains(s.phase)) {
            ik.pullNullSpace(s.ikSolution, armRestPosture, armRest.gain());
        }
        for (int d : ik.dofs()) {
            s.targets[d] = s.ikSolution[d];
        }
        double w = Math.max(0, Math.min(1, (obs.time() - s.poseStart) / s.poseDuration));
        poses.slerp(s.poseFrom, poses.pose(s.handPose), w, s.targets);
    }

    /**
     * Sums the object's end-over-end turns tick by tick from the last tick it touched the hand (the
     * flip criterion's release is the tick after, one tick's turn less): what the catch's level
     * search adds its predicted turn to.
     */
    private void followTurn(Observation obs, ControllerState s) {
        if (object.longAxis().isEmpty()) {
            return;
        }
        Vec3 axis = obs.object().orientation().rotate(object.longAxis().get());
        if (obs.handTouchedObject()) {
            s.turnSinceTouch = Vec3.ZERO;
        } else if (s.turnSinceTouch != null) {
            s.turnSinceTouch = s.turnSinceTouch.plus(EndOverEnd.step(s.objectAxis, axis));
        }
        s.objectAxis = axis;
    }

    /** The state has run its time; with a {@link ClosedLoopRelease}, THROW ends on the object's predicted turn. */
    private boolean stateOver(Observation obs, ControllerState s) {
        double t = obs.time() - s.phaseStart;
        if (s.phase != Phase.THROW || config.release().isEmpty() || object.longAxis().isEmpty()) {
            return t >= duration(s);
        }
        Vec3 axis = obs.object().orientation().rotate(object.longAxis().get());
        double predicted = ClosedLoopRelease.predictedTurn(obs.object(), axis, ballistics, config.interceptionHeight());
        return config.release().get().throwOver(t, duration(s), predicted);
    }

    private double duration(ControllerState s) {
        return switch (s.phase) {
            case CATCH -> s.catchEnd - s.phaseStart;
            case MIDDLE -> config.middleDuration();
            case THROW -> config.throwDuration();
            case GOBACK -> config.gobackDuration();
        };
    }

    /** Plans the curve of a new state from the hand's current position and velocity (sec. 3.6). */
    private void enter(Phase phase, Observation obs, ControllerState s, ThrowDecision decision) {
        Vec3 p0 = obs.palm().origin();
        Vec3 v0 = obs.palmVelocity();
        Quat r0 = obs.palm().rotation();
        s.phase = phase;
        s.phaseStart = obs.time();
        s.trajectoryStart = obs.time();
        switch (phase) {
            case CATCH -> {
                planCatch(obs, p0, v0, r0, s);
                s.closedOnContact = false;
                blendTo(HandPose.OPEN, config.openTime(), obs.time(), s);
            }
            case MIDDLE -> s.trajectory = new PalmTrajectory(new Hermite(p0, v0, neutralPalm.origin(), Vec3.ZERO,
                    config.middleDuration()), r0, neutralPalm.rotation());
            case THROW -> {
                ThrowParameters p = decision.throwing();
                s.currentThrow = p;
                s.catchStyle = decision.catching() != null ? decision.catching() : config.catchAfterThrow().orElse(null);
                double tt = config.throwDuration();
                Vec3 endVelocity = p.dOffset().times(config.throwEndSpeedFactor() / tt);
                Quat end = Quat.fromRotationVector(p.rTarget()).mul(neutralPalm.rotation());
                s.trajectory = new PalmTrajectory(new Hermite(p0, v0, p0.plus(p.dOffset()), endVelocity, tt), r0, end);
            }
            case GOBACK -> {
                Vec3 rest = new Vec3(p0.x(), config.restPlaneHeight(), p0.z());
                s.trajectory = new PalmTrajectory(new Hermite(p0, v0, rest, Vec3.ZERO, config.gobackDuration()), r0,
                        neutralPalm.rotation());
                blendTo(HandPose.NEUTRAL, config.neutralTime(), obs.time(), s);
            }
        }
    }

    /**
     * The CATCH curve from the palm state (p0, v0, r0) to the interception planned from the
     * object's state now (sec. 3.6); CATCH ends at the interception.
     */
    private void planCatch(Observation obs, Vec3 p0, Vec3 v0, Quat r0, ControllerState s) {
        CatchPlanner.Plan plan = planner.plan(obs.object(), object, grasp, neutralPalm.rotation(),
                palm -> ik.solve(s.ikSolution.clone(), palm, config.reachIkIterations()),
                s.catchStyle == null ? config.catchStyle() : s.catchStyle, s.turnSinceTouch);
        s.plan = plan;
        s.plannedFrom = obs.object();
        s.plannedAt = obs.time();
        s.catchEnd = obs.time() + plan.duration();
        s.trajectory = new PalmTrajectory(new Hermite(p0, v0, plan.palmTarget().origin(), plan.palmVelocity(),
                plan.duration()), r0, plan.palmTarget().rotation());
    }

    /** The object's velocity differs from the ballistic prediction of the plan by more than the configured change. */
    private boolean leftPredictedFlight(Observation obs, ControllerState s) {
        Vec3 predicted = ballistics.velocity(s.plannedFrom.velocity(), obs.time() - s.plannedAt);
        return obs.object().velocity().distance(predicted) > config.replanSpeedChange();
    }

    /** A new CATCH curve from where the current one stands now, so the palm target moves on smoothly. */
    private void replanCatch(Observation obs, ControllerState s) {
        double t = obs.time() - s.trajectoryStart;
        Frame at = s.trajectory.at(t);
        Vec3 v = s.trajectory.velocity(Math.min(t, s.trajectory.duration()));
        s.trajectoryStart = obs.time();
        planCatch(obs, at.origin(), v, at.rotation(), s);
    }

    /** Starts a SLERP of the finger targets from where they are now to {@code pose}. */
    private void blendTo(HandPose pose, double duration, double time, ControllerState s) {
        double[] w = s.poseWeights(time);
        s.weightsFrom = w;
        System.arraycopy(s.targets, 0, s.poseFrom, 0, s.targets.length);
        s.handPose = pose;
        s.poseStart = time;
        s.poseDuration = duration;
    }
}
