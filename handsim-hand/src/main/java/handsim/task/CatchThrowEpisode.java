package handsim.task;

import handsim.control.CatchStyle;
import handsim.control.ControllerConfig;
import handsim.control.ControllerState;
import handsim.control.NominalController;
import handsim.control.Observation;
import handsim.control.PdController;
import handsim.control.Phase;
import handsim.control.ThrowDecision;
import handsim.kin.Frame;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.model.Site;
import handsim.sim.ObjectSpec;
import handsim.sim.RigidState;
import handsim.sim.Simulator;
import handsim.sim.WorldSnapshot;
import handsim.sim.WorldState;
import java.util.List;

/**
 * Catch-and-throw loops of one object with a {@link NominalController} on a {@link ThrowTask}:
 * the arm starts at rest in the neutral pose, the object is launched toward it, and the
 * controller catches and throws until the object is dropped or a loop is cut off by time. The
 * object is moved only by gravity, damping and contacts: nothing here touches it after the
 * launch.
 *
 * <p>A tick is one controller period: whole physics steps, then the controller's reaction. The
 * catch of a loop is judged when MIDDLE ends; the episode then stops at the decision of the
 * next THROW. {@link #advanceToDecision} ticks to that point and {@link #decide} makes the
 * throw, so that a learner, a planner or a throw policy chooses it (one decision per THROW,
 * sec. 3.7) in the same way. The episode's whole state is a world state and an {@link
 * EpisodeState} ({@link #checkpoint}, {@link #restore}).
 */
public final class CatchThrowEpisode {

    /** How the episode stands after a tick. */
    public enum Status { RUNNING, DROPPED, TIME_LIMIT }

    private final Simulator sim;
    private final ServoLoop loop;
    private final NominalController controller;
    private final ThrowTask task;
    private final EpisodeLimits limits;
    private final HandModel model;
    private final Site palm;
    private final int periodSteps;
    private final double[] q;
    private final double[] qd;
    /** The object's position, read every physics step without allocating. */
    private final double[] objectPosition = new double[3];
    /** What the world holds besides the arm, set at the start or restore. */
    private List<WorldSnapshot.StaticBox> boxes = List.of();
    private Vec3 longAxis;
    private double objectRadius;
    /** Everything of the episode besides the world (see {@link EpisodeState}). */
    private EpisodeState state;

    /** {@code task} sets each throw's goal; the decisions read it. */
    public CatchThrowEpisode(Simulator sim, PdController pd, NominalController controller, ThrowTask task,
            EpisodeLimits limits) {
        this.sim = sim;
        this.task = task;
        this.loop = new ServoLoop(sim, pd);
        this.controller = controller;
        this.limits = limits;
        this.model = sim.model();
        this.palm = model.site("palm_center");
        this.periodSteps = controller.config().periodSteps();
        this.q = new double[model.dofCount()];
        this.qd = new double[model.dofCount()];
    }

    /**
     * An episode with this one's model, controller settings, object, task and limits on {@code
     * other} (a simulator with an engine of its own): a twin to {@link #restore} this episode's
     * checkpoints into.
     */
    public CatchThrowEpisode twinOn(Simulator other) {
        ControllerConfig cc = controller.config();
        return new CatchThrowEpisode(other, new PdController(other.model(), cc.pd()),
                new NominalController(other.model(), cc, controller.object(), other.config().gravity()), task, limits);
    }

    /** Resets the world (arm at rest in the neutral pose), sets up the task's episode and launches {@code object}. */
    public void start(ObjectSpec object, RigidState launch, long seed) {
        sim.reset(model.poseVector("neutral"), seed);
        task.start(sim, seed);
        setUp(object);
        sim.spawnObject(object, launch);
        state = new EpisodeState(null, new FlightTracker(sim.config().gravity().negate()));
        startController(null);
        beginLoop();
    }

    /**
     * Before the first tick: the controller starts again from the same observation, meeting the
     * launched object as {@code style} says (null: its own way): a throw planner's choice.
     */
    public void catchThrowInAs(CatchStyle style) {
        if (!state.loops.isEmpty() || sim.time() != state.loop.loopStart || state.decision != null) {
            throw new IllegalStateException("the throw-in's catch is chosen before the episode's first tick");
        }
        startController(style);
    }

    private void startController(CatchStyle throwIn) {
        state.controller = controller.start(observe(), throwIn);
        System.arraycopy(state.controller.targets(), 0, loop.targets(), 0, q.length);
    }

    /** The object's shape, and the boxes of the world it flies in. */
    private void setUp(ObjectSpec object) {
        boxes = sim.staticBoxes();
        longAxis = object.longAxis().orElse(null);
        objectRadius = object.boundingRadius();
    }

    public Simulator sim() {
        return sim;
    }

    public ThrowTask task() {
        return task;
    }

    /** The episode's own state (live: what {@link #checkpoint} copies). */
    public EpisodeState state() {
        return state;
    }

    public ControllerState controllerState() {
        return state.controller;
    }

    public Status status() {
        return state.status;
    }

    /** The apex height the throw now in progress aims at (m; NaN before the first throw or without a height goal). */
    public double throwGoal() {
        return state.loop.loopGoal;
    }

    /** Finished loops, in order. */
    public List<LoopRecord> loops() {
        return state.loops;
    }

    /** The episode so far, as a result. */
    public EpisodeResult result(long seed) {
        return new EpisodeResult(seed, state.loops, state.status);
    }

    /**
     * Everything the episode needs to go on from a tick: the world and the episode's own state.
     * Not the task's goal: restore into an episode whose task stands at the same goal (the flip
     * task has one for every throw).
     */
    public record Checkpoint(WorldState world, EpisodeState episode) {

        /** Loops finished before the checkpoint. */
        public int loopCount() {
            return episode.loops().size();
        }
    }

    /** The episode now, to go on from later or in a twin episode ({@link #restore}). */
    public Checkpoint checkpoint() {
        return new Checkpoint(sim.captureState(), state.copy());
    }

    /**
     * Puts this episode, its world and its controller where {@code c} was taken, from this
     * episode or another of the same model, controller settings and object; it then runs on
     * exactly as that episode did (the world steps on bit for bit, {@link Simulator#restoreState}).
     */
    public void restore(Checkpoint c) {
        ObjectSpec object = c.world().objectSpec().orElseThrow(() -> new IllegalArgumentException("the checkpoint has no object"));
        if (!object.equals(controller.object())) {
            throw new IllegalArgumentException("the checkpoint holds a " + object.name() + " of " + object.mass().mass()
                    + " kg, this episode's controller catches a " + controller.object().name() + " of "
                    + controller.object().mass().mass() + " kg: restore into an episode made for the same object");
        }
        sim.restoreState(c.world());
        setUp(object);
        state = c.episode().copy();
        System.arraycopy(state.controller.targets(), 0, loop.targets(), 0, q.length);
    }

    /** The observation the episode waits at for a throw's decision ({@link #advanceToDecision}), or null when not at one. */
    public Observation decision() {
        return state.decision;
    }

    /** The observation the controller sees now. */
    public Observation observe() {
        sim.readJoints(q, qd);
        Frame palmFrame = sim.bodyFrame(palm.body()).compose(new Frame(palm.position(), palm.orientation()));
        Vec3 palmVelocity = sim.pointVelocity(palm.body(), palm.position());
        return new Observation(sim.time(), q.clone(), qd.clone(), palmFrame, palmVelocity, sim.objectState(), state.touchedSinceTick);
    }

    /**
     * Ticks until the controller is about to begin a THROW (the catch before it judged and
     * recorded) and returns the observation the throw is decided on ({@link #decide}); at once
     * when the episode already waits there. Returns null when the episode ended first.
     */
    public Observation advanceToDecision() {
        requireRunning();
        while (state.decision == null) {
            tick();
            if (state.status != Status.RUNNING) {
                return null;
            }
        }
        return state.decision;
    }

    /** At a decision ({@link #advanceToDecision}): the controller begins the THROW that {@code decision} says. */
    public void decide(ThrowDecision decision) {
        if (state.decision == null) {
            throw new IllegalStateException("the episode is not at a throw's decision");
        }
        Observation obs = state.decision;
        state.decision = null;
        Phase before = state.controller.phase();
        controller.beginThrow(obs, state.controller, decision);
        afterReaction(before);
    }

    /**
     * Runs one controller period (a whole number of physics steps), then lets the controller
     * react; when a throw is due the episode judges the catch and stops at the decision ({@link
     * #decision}) instead, until {@link #decide}. Returns the loop record finished during this
     * tick, or null.
     */
    public LoopRecord tick() {
        requireRunning();
        if (state.decision != null) {
            throw new IllegalStateException("the episode waits at a throw's decision: decide it first");
        }
        LoopRecord dropped = advancePhysics();
        if (dropped != null) {
            return dropped;
        }
        Observation obs = takeObservation();
        if (controller.throwDue(obs, state.controller)) {
            LoopRecord judged = judgeCatch(obs);
            if (state.status == Status.RUNNING) {
                state.decision = obs;
            }
            return judged;
        }
        Phase before = state.controller.phase();
        controller.update(obs, state.controller);
        return afterReaction(before);
    }

    /**
     * After {@link #decide}: ticks until THROW is over, the hand in GOBACK and the coming catch not
     * yet planned ({@link #meetComingCatchAs} may still choose it). False when the episode ended first.
     */
    public boolean advanceToThrowEnd() {
        while (state.status == Status.RUNNING && state.controller.phase() == Phase.THROW) {
            tick();
        }
        return state.status == Status.RUNNING;
    }

    /** In THROW or GOBACK: the coming catch meets the object as {@code style} says ({@link NominalController#meetComingCatchAs}). */
    public void meetComingCatchAs(CatchStyle style) {
        controller.meetComingCatchAs(state.controller, style);
    }

    private void requireRunning() {
        if (state.status != Status.RUNNING) {
            throw new IllegalStateException("episode is over: " + state.status);
        }
    }

    /** The physics of one controller period; the loop record if the object was dropped. */
    private LoopRecord advancePhysics() {
        EpisodeState.LoopStats current = state.loop;
        for (int i = 0; i < periodSteps; i++) {
            current.peakTorqueRatio = Math.max(current.peakTorqueRatio, loop.step());
            state.touchedSinceTick |= sim.handContacts().bodyMask();
            current.maxDepth = Math.max(current.maxDepth, sim.handContacts().maxDepth());
            current.boxHit |= sim.objectTouchesBox();
            sim.objectPosition(objectPosition);
            current.apex = Math.max(current.apex, objectPosition[1]);
            if (sim.objectTouchesGround() || distanceFromShoulder(objectPosition) > limits.maxDistance()) {
                current.landing = Vec3.of(objectPosition);
                state.status = Status.DROPPED;
                return finishLoop(false);
            }
        }
        return null;
    }

    /** The observation at the end of a period, with the loop's per-tick statistics updated from it. */
    private Observation takeObservation() {
        Observation obs = observe();
        state.touchedSinceTick = 0;
        EpisodeState.LoopStats current = state.loop;
        for (int i = 0; i < q.length; i++) {
            current.maxLimitExcess = Math.max(current.maxLimitExcess, model.dofs().get(i).limitExcess(obs.q()[i]));
        }
        for (WorldSnapshot.StaticBox b : boxes) {
            double d = Math.max(0, distanceToBox(obs.object().position(), b) - objectRadius);
            current.boxDistance = Math.min(current.boxDistance, d);
        }
        trackFlight(obs);
        return obs;
    }

    /** Follows the loop's throw in flight, from the release to the catch (see {@link FlightTracker}). */
    private void trackFlight(Observation obs) {
        if (state.loops.isEmpty()) {
            return;
        }
        RigidState o = obs.object();
        state.flight.observe(obs.handTouchedObject(), state.controller.phase() != Phase.MIDDLE, o.position(), o.velocity(),
                longAxis == null ? null : o.orientation().rotate(longAxis), o.angularVelocity());
    }

    /** After the controller reacted: a loop begins with a THROW; the loop record if the loop ran out of time. */
    private LoopRecord afterReaction(Phase before) {
        System.arraycopy(state.controller.targets(), 0, loop.targets(), 0, q.length);
        if (before == Phase.MIDDLE && state.controller.phase() == Phase.THROW) {
            beginLoop();
        } else if (sim.time() - state.loop.loopStart > limits.maxLoopSeconds()) {
            state.status = Status.TIME_LIMIT;
            return finishLoop(false);
        }
        return null;
    }

    /**
     * The catch is judged when MIDDLE ends: is the object resting in the hand? For a long object
     * also how far its axis stands out of the palm's plane (a task may ask for it to lie in it).
     */
    private LoopRecord judgeCatch(Observation obs) {
        boolean held = obs.object().position().distance(obs.palm().origin()) < limits.holdDistance();
        if (!held) {
            state.loop.landing = obs.object().position();
            state.status = Status.DROPPED;
        } else if (longAxis != null) {
            LyingPose pose = LyingPose.of(obs.palm(), obs.object().orientation().rotate(longAxis)); // unit: ObjectSpec normalises it
            state.loop.catchTilt = pose.tilt();
            state.loop.catchHeading = pose.heading();
        }
        return finishLoop(held);
    }

    /** |p - shoulder anchor|, as Vec3.distance computes it. */
    private double distanceFromShoulder(double[] p) {
        Vec3 a = model.joints().get(0).anchor();
        double dx = p[0] - a.x(), dy = p[1] - a.y(), dz = p[2] - a.z();
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    private void beginLoop() {
        EpisodeState.LoopStats current = new EpisodeState.LoopStats();
        current.loopStart = sim.time();
        state.flight.reset();
        current.loopThrow = state.loops.isEmpty() ? null : state.controller.currentThrow();
        current.loopGoal = state.loops.isEmpty() ? Double.NaN : task.targetHeight();
        if (!state.loops.isEmpty()) {
            task.advance(); // the throw of this loop is made: the next one aims at its own goal
        }
        state.loop = current;
    }

    private LoopRecord finishLoop(boolean caught) {
        int index = state.loops.size();
        EpisodeState.LoopStats c = state.loop;
        FlightTracker flight = state.flight;
        if (!caught && c.landing == null) {
            c.landing = sim.objectState().position();
        }
        LoopRecord r = new LoopRecord(index, caught, index == 0 ? Double.NaN : c.apex, caught ? null : c.landing,
                c.loopGoal, c.loopThrow, c.boxHit, boxes.isEmpty() ? Double.NaN : c.boxHit ? 0 : c.boxDistance,
                index == 0 || longAxis == null ? Double.NaN : flight.rotation(),
                index == 0 ? Double.NaN : flight.releaseSpin(), c.catchTilt, c.catchHeading, flight.catchPoint(),
                index == 0 || longAxis == null ? Double.NaN : flight.arrivalTilt(),
                c.maxDepth, c.maxLimitExcess, c.peakTorqueRatio, sim.time() - c.loopStart);
        state.loops.add(r);
        return r;
    }

    /** Distance (m) from a point to a box (0 inside). */
    static double distanceToBox(Vec3 p, WorldSnapshot.StaticBox b) {
        Vec3 c = b.center(), h = b.size().times(0.5);
        double dx = Math.max(0, Math.abs(p.x() - c.x()) - h.x());
        double dy = Math.max(0, Math.abs(p.y() - c.y()) - h.y());
        double dz = Math.max(0, Math.abs(p.z() - c.z()) - h.z());
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
