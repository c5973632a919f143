package handsim.task;

import handsim.control.CatchStyle;
import handsim.control.ControllerConfig;
import handsim.control.ControllerState;
import handsim.control.NominalController;
import handsim.control.Observation;
import handsim.control.PdController;
import handsim.control.Phase;
import handsim.control.ThrowParameters;
import handsim.control.ThrowPolicy;
import handsim.kin.Frame;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.model.Site;
import handsim.sim.ObjectSpec;
import handsim.sim.RigidState;
import handsim.sim.Simulator;
import handsim.sim.WorldSnapshot;
import handsim.sim.WorldState;
import java.util.ArrayList;
import java.util.List;

/**
 * Catch-and-throw loops of one object with a {@link NominalController} on a {@link ThrowTask}:
 * the arm starts at rest in the neutral pose, the object is launched toward it, and the
 * controller catches and throws until the object is dropped or a loop is cut off by time. The
 * object is moved only by gravity, damping and contacts: nothing here touches it after the
 * launch.
 *
 * <p>A tick is one controller period: whole physics steps, then the controller's reaction. The
 * catch of a loop is judged when MIDDLE ends, just before the controller asks its throw policy
 * for the next THROW. {@link #runUntilThrowDue} stops exactly there, so that a learner can choose
 * that throw (one decision per THROW, sec. 3.7).
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
    private final List<LoopRecord> loops = new ArrayList<>();
    private ControllerState state;
    private Status status = Status.RUNNING;
    private long touchedSinceTick;
    private List<WorldSnapshot.StaticBox> boxes = List.of();
    private Vec3 longAxis;
    private FlightTracker flight;
    private double objectRadius;
    /** The observation the episode stopped at, waiting for the throw to be chosen; null when not waiting. */
    private Observation waiting;
    /** Statistics of the loop in progress. */
    private LoopProgress current = new LoopProgress();

    /** {@code task} sets each throw's goal; the controller's throw policy reads it. */
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
        this.flight = new FlightTracker(sim.config().gravity().negate());
    }

    /** Resets the world (arm at rest in the neutral pose), sets up the task's episode and launches {@code object}. */
    public void start(ObjectSpec object, RigidState launch, long seed) {
        sim.reset(model.poseVector("neutral"), seed);
        task.start(sim, seed);
        boxes = sim.staticBoxes();
        longAxis = object.longAxis().orElse(null);
        objectRadius = object.boundingRadius();
        sim.spawnObject(object, launch);
        loops.clear();
        status = Status.RUNNING;
        touchedSinceTick = 0;
        waiting = null;
        state = controller.start(observe());
        System.arraycopy(state.targets(), 0, loop.targets(), 0, q.length);
        beginLoop();
    }

    /**
     * Before the first tick: the controller starts again from the same observation, meeting the
     * launched object as {@code style} says (null: its own way). A planner chooses it ({@link
     * ThrowPlanner#chooseThrowInCatch}).
     */
    public void catchThrowInAs(CatchStyle style) {
        if (!loops.isEmpty() || sim.time() != current.loopStart || waiting != null) {
            throw new IllegalStateException("the throw-in's catch is chosen before the episode's first tick");
        }
        state = controller.start(observe(), style);
        System.arraycopy(state.targets(), 0, loop.targets(), 0, q.length);
    }

    public Simulator sim() {
        return sim;
    }

    /**
     * An episode with this one's model, controller settings, object, task and limits on {@code
     * other} (a simulator with an engine of its own), whose controller throws what {@code
     * throwPolicy} says: a twin to {@link #restore} this episode's checkpoints into.
     */
    public CatchThrowEpisode twinOn(Simulator other, ThrowPolicy throwPolicy) {
        ControllerConfig cc = controller.config();
        return new CatchThrowEpisode(other, new PdController(other.model(), cc.pd()),
                new NominalController(other.model(), cc, controller.object(), throwPolicy, other.config().gravity()), task, limits);
    }

    public ThrowTask task() {
        return task;
    }

    public ControllerState state() {
        return state;
    }

    public Status status() {
        return status;
    }

    /** The apex height the throw now in progress aims at (m; NaN before the first throw or without a height goal). */
    public double throwGoal() {
        return current.loopGoal;
    }

    /** Finished loops, in order. */
    public List<LoopRecord> loops() {
        return loops;
    }

    /** The episode so far, as a result. */
    public EpisodeResult result(long seed) {
        return new EpisodeResult(seed, loops, status);
    }

    /**
     * Everything the episode needs to go on from a tick: the world, the controller's state, the
     * loops so far and the statistics of the loop in progress. Not the task's goal: restore into
     * an episode whose task stands at the same goal (the flip task has one for every throw).
     */
    public static final class Checkpoint {
        private final WorldState world;
        private final ControllerState state;
        private final double[] targets;
        private final double peakTorqueRatio;
        private final List<LoopRecord> loops;
        private final Status status;
        private final long touchedSinceTick;
        private final Observation waiting;
        private final FlightTracker flight;
        private final LoopProgress current;

        private Checkpoint(CatchThrowEpisode e) {
            world = e.sim.captureState();
            state = e.state.copy();
            targets = e.loop.targets().clone();
            peakTorqueRatio = e.loop.peakTorqueRatio();
            loops = List.copyOf(e.loops);
            status = e.status;
            touchedSinceTick = e.touchedSinceTick;
            waiting = e.waiting;
            flight = e.flight.copy();
            current = e.current.copy();
        }

        /** The world as it was. */
        public WorldState world() {
            return world;
        }

        /** Loops finished before the checkpoint. */
        public int loopCount() {
            return loops.size();
        }
    }

    /** The episode now, to go on from later or in a twin episode ({@link #restore}). */
    public Checkpoint checkpoint() {
        return new Checkpoint(this);
    }

    /**
     * Puts this episode, its world and its controller where {@code c} was taken, from this
     * episode or another of the same model, controller settings and object; it then runs on
     * exactly as that episode did (the world steps on bit for bit, {@link Simulator#restoreState}).
     */
    public void restore(Checkpoint c) {
        ObjectSpec object = c.world.objectSpec().orElseThrow(() -> new IllegalArgumentException("the checkpoint has no object"));
        if (!object.equals(controller.object())) {
            throw new IllegalArgumentException("the checkpoint holds a " + object.name() + " of " + object.mass().mass()
                    + " kg, this episode's controller catches a " + controller.object().name() + " of "
                    + controller.object().mass().mass() + " kg: restore into an episode made for the same object");
        }
        sim.restoreState(c.world);
        boxes = c.world.boxes();
        longAxis = object.longAxis().orElse(null);
        objectRadius = object.boundingRadius();
        state = c.state.copy();
        System.arraycopy(c.targets, 0, loop.targets(), 0, c.targets.length);
        loop.restorePeakTorqueRatio(c.peakTorqueRatio);
        loops.clear();
        loops.addAll(c.loops);
        status = c.status;
        touchedSinceTick = c.touchedSinceTick;
        waiting = c.waiting;
        flight = c.flight.copy();
        current = c.current.copy();
    }

    /** The observation the episode stopped at to wait for a throw ({@link #runUntilThrowDue}), or null when not waiting. */
    public Observation waiting() {
        return waiting;
    }

    /** The observation the controller sees now. */
    public Observation observe() {
        sim.readJoints(q, qd);
        Frame palmFrame = sim.bodyFrame(palm.body()).compose(new Frame(palm.position(), palm.orientation()));
        Vec3 palmVelocity = sim.pointVelocity(palm.body(), palm.position());
        return new Observation(sim.time(), q.clone(), qd.clone(), palmFrame, palmVelocity, sim.objectState(), touchedSinceTick);
    }

    /**
     * Runs one controller period (a whole number of physics steps), then lets the controller
     * react. Returns the loop record finished during this tick, or null. An episode stopped by
     * {@link #runUntilThrowDue} goes on from there: the controller asks its throw policy now.
     */
    public LoopRecord tick() {
        requireRunning();
        if (waiting != null) {
            resume();
            return null;
        }
        LoopRecord r = tickOrWait();
        if (waiting != null) {
            resume(); // the throw is asked for in the same tick as the catch is judged
        }
        return r;
    }

    /**
     * Ticks until the controller is about to choose a THROW (the catch before it judged and
     * recorded) and returns the observation it will choose on; the episode then waits for the
     * throw policy, which is asked by the next {@link #tick()} or {@link #resume()}. Returns
     * null when the episode ended first.
     */
    public Observation runUntilThrowDue() {
        requireRunning();
        while (waiting == null) {
            tickOrWait();
            if (status != Status.RUNNING) {
                return null;
            }
        }
        return waiting;
    }

    /**
     * One tick as {@link #tick}, except that when a throw is due the episode judges the catch and
     * stops to wait for the throw ({@link #waiting}) instead of asking the throw policy; {@link
     * #resume} goes on. Returns the loop record finished during this tick, or null.
     */
    public LoopRecord tickOrWait() {
        requireRunning();
        if (waiting != null) {
            throw new IllegalStateException("the episode is waiting for a throw: resume it first");
        }
        LoopRecord dropped = advancePhysics();
        if (dropped != null) {
            return dropped;
        }
        Observation obs = takeObservation();
        if (controller.throwDue(obs, state)) {
            LoopRecord judged = judgeCatch(obs);
            if (status == Status.RUNNING) {
                waiting = obs;
            }
            return judged;
        }
        return react(obs);
    }

    /**
     * After {@link #resume}: ticks until THROW is over, the hand in GOBACK and the coming catch not
     * yet planned ({@link #meetComingCatchAs} may still choose it). False when the episode ended first.
     */
    public boolean runUntilThrowEnds() {
        while (status == Status.RUNNING && state.phase() == Phase.THROW) {
            tickOrWait();
        }
        return status == Status.RUNNING;
    }

    /** In THROW or GOBACK: the coming catch meets the object as {@code style} says ({@link NominalController#meetComingCatchAs}). */
    public void meetComingCatchAs(CatchStyle style) {
        controller.meetComingCatchAs(state, style);
    }

    /** Goes on from {@link #runUntilThrowDue}: the controller asks its throw policy and begins the THROW. */
    public void resume() {
        if (waiting == null) {
            throw new IllegalStateException("the episode is not waiting for a throw");
        }
        Observation obs = waiting;
        waiting = null;
        react(obs);
    }

    private void requireRunning() {
        if (status != Status.RUNNING) {
            throw new IllegalStateException("episode is over: " + status);
        }
    }

    /** The physics of one controller period; the loop record if the object was dropped. */
    private LoopRecord advancePhysics() {
        for (int i = 0; i < periodSteps; i++) {
            loop.step();
            touchedSinceTick |= sim.handContacts().bodyMask();
            current.maxDepth = Math.max(current.maxDepth, sim.handContacts().maxDepth());
            current.boxHit |= sim.objectTouchesBox();
            sim.objectPosition(objectPosition);
            current.apex = Math.max(current.apex, objectPosition[1]);
            if (sim.objectTouchesGround() || distanceFromShoulder(objectPosition) > limits.maxDistance()) {
                current.landing = Vec3.of(objectPosition);
                status = Status.DROPPED;
                return finishLoop(false);
            }
        }
        return null;
    }

    /** The observation at the end of a period, with the loop's per-tick statistics updated from it. */
    private Observation takeObservation() {
        Observation obs = observe();
        touchedSinceTick = 0;
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
        if (loops.isEmpty()) {
            return;
        }
        RigidState o = obs.object();
        flight.observe(obs.handTouchedObject(), state.phase() != Phase.MIDDLE, o.position(), o.velocity(),
                longAxis == null ? null : o.orientation().rotate(longAxis), o.angularVelocity());
    }

    /** The controller's reaction to an observation; the loop record if the loop ran out of time. */
    private LoopRecord react(Observation obs) {
        Phase before = state.phase();
        controller.update(obs, state);
        System.arraycopy(state.targets(), 0, loop.targets(), 0, q.length);
        if (before == Phase.MIDDLE && state.phase() == Phase.THROW) {
            beginLoop();
        } else if (sim.time() - current.loopStart > limits.maxLoopSeconds()) {
            status = Status.TIME_LIMIT;
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
            current.landing = obs.object().position();
            status = Status.DROPPED;
        } else if (longAxis != null) {
            Vec3 axis = obs.object().orientation().rotate(longAxis); // unit: ObjectSpec normalises it
            current.catchTilt = Math.asin(Math.min(1, Math.abs(axis.dot(obs.palm().rotation().yAxis())))); // palm y: its normal
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
        current = new LoopProgress();
        current.loopStart = sim.time();
        flight.reset();
        current.loopThrow = loops.isEmpty() ? null : state.currentThrow();
        current.loopGoal = loops.isEmpty() ? Double.NaN : task.targetHeight();
        if (!loops.isEmpty()) {
            task.advance(); // the throw of this loop is made: the next one aims at its own goal
        }
        loop.resetPeakTorqueRatio();
    }

    private LoopRecord finishLoop(boolean caught) {
        int index = loops.size();
        if (!caught && current.landing == null) {
            current.landing = sim.objectState().position();
        }
        LoopProgress c = current;
        LoopRecord r = new LoopRecord(index, caught, index == 0 ? Double.NaN : c.apex, caught ? null : c.landing,
                c.loopGoal, c.loopThrow, c.boxHit, boxes.isEmpty() ? Double.NaN : c.boxHit ? 0 : c.boxDistance,
                index == 0 || longAxis == null ? Double.NaN : flight.rotation(),
                index == 0 ? Double.NaN : flight.releaseSpin(), c.catchTilt, flight.catchPoint(),
                index == 0 || longAxis == null ? Double.NaN : flight.arrivalTilt(),
                c.maxDepth, c.maxLimitExcess, loop.peakTorqueRatio(), sim.time() - c.loopStart);
        loops.add(r);
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

    /** The statistics of a loop while it runs, copied whole into a checkpoint. */
    private static final class LoopProgress {
        double loopStart;
        double apex = Double.NEGATIVE_INFINITY;
        double maxDepth;
        double maxLimitExcess;
        boolean boxHit;
        double boxDistance = Double.POSITIVE_INFINITY;
        Vec3 landing;
        /** The judged catch's tilt of the long axis out of the palm plane (see {@link LoopRecord#catchTilt}). */
        double catchTilt = Double.NaN;
        ThrowParameters loopThrow;
        double loopGoal = Double.NaN;

        LoopProgress copy() {
            LoopProgress c = new LoopProgress();
            c.loopStart = loopStart;
            c.apex = apex;
            c.maxDepth = maxDepth;
            c.maxLimitExcess = maxLimitExcess;
            c.boxHit = boxHit;
            c.boxDistance = boxDistance;
            c.landing = landing;
            c.catchTilt = catchTilt;
            c.loopThrow = loopThrow;
            c.loopGoal = loopGoal;
            return c;
        }
    }
}
