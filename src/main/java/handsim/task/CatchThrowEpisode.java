package handsim.task;

import handsim.control.ControllerState;
import handsim.control.NominalController;
import handsim.control.Observation;
import handsim.control.Phase;
import handsim.control.ThrowParameters;
import handsim.control.PdController;
import handsim.kin.Frame;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.model.Site;
import handsim.sim.ObjectSpec;
import handsim.sim.RigidState;
import handsim.sim.Simulator;
import java.util.ArrayList;
import java.util.List;

/**
 * Catch-and-throw loops of one object with a {@link NominalController}: the arm starts at rest
 * in the neutral pose, the object is launched toward it, and the controller catches and throws
 * until the object is dropped or a loop is cut off by time. The object is moved only by
 * gravity, damping and contacts: nothing here touches it after the launch.
 */
public final class CatchThrowEpisode {

    /** How the episode stands after a tick. */
    public enum Status { RUNNING, DROPPED, TIME_LIMIT }

    private final Simulator sim;
    private final ServoLoop loop;
    private final NominalController controller;
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
    private Phase lastPhase;
    // statistics of the loop in progress
    private double loopStart;
    private double apex;
    private double maxDepth;
    private double maxLimitExcess;
    private boolean touchedSinceTick;
    private Vec3 landing;
    private ThrowParameters loopThrow;
    private double loopGoal = Double.NaN;
    private final HeightGoals goals;

    /** {@code goals} are the desired apex heights the controller's throw policy reads. */
    public CatchThrowEpisode(Simulator sim, PdController pd, NominalController controller, HeightGoals goals,
            EpisodeLimits limits) {
        this.sim = sim;
        this.goals = goals;
        this.loop = new ServoLoop(sim, pd);
        this.controller = controller;
        this.limits = limits;
        this.model = sim.model();
        this.palm = model.site("palm_center");
        this.periodSteps = controller.config().periodSteps();
        this.q = new double[model.dofCount()];
        this.qd = new double[model.dofCount()];
    }

    /** Resets the world (arm at rest in the neutral pose) and launches {@code object}. */
    public void start(ObjectSpec object, RigidState launch, long seed) {
        sim.reset(model.poseVector("neutral"), seed);
        goals.reset(seed);
        sim.spawnObject(object, launch);
        loops.clear();
        status = Status.RUNNING;
        touchedSinceTick = false;
        state = controller.start(observe());
        lastPhase = state.phase();
        System.arraycopy(state.targets(), 0, loop.targets(), 0, q.length);
        beginLoop();
    }

    public Simulator sim() {
        return sim;
    }

    public ControllerState state() {
        return state;
    }

    public Status status() {
        return status;
    }

    /** Finished loops, in order. */
    public List<LoopRecord> loops() {
        return loops;
    }

    /** The episode so far, as a result. */
    public EpisodeResult result(long seed) {
        return new EpisodeResult(seed, loops, status);
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
     * react. Returns the loop record finished during this tick, or null.
     */
    public LoopRecord tick() {
        if (status != Status.RUNNING) {
            throw new IllegalStateException("episode is over: " + status);
        }
        for (int i = 0; i < periodSteps; i++) {
            loop.step();
            touchedSinceTick |= sim.handContacts().any();
            maxDepth = Math.max(maxDepth, sim.handContacts().maxDepth());
            sim.objectPosition(objectPosition);
            apex = Math.max(apex, objectPosition[1]);
            if (sim.objectTouchesGround() || distanceFromShoulder(objectPosition) > limits.maxDistance()) {
                landing = Vec3.of(objectPosition);
                status = Status.DROPPED;
                return finishLoop(false);
            }
        }
        Observation obs = observe();
        touchedSinceTick = false;
        for (int i = 0; i < q.length; i++) {
            maxLimitExcess = Math.max(maxLimitExcess, model.dofs().get(i).limitExcess(obs.q()[i]));
        }
        controller.update(obs, state);
        System.arraycopy(state.targets(), 0, loop.targets(), 0, q.length);
        LoopRecord finished = null;
        if (lastPhase == Phase.MIDDLE && state.phase() == Phase.THROW) {
            // the catch is judged when MIDDLE ends: is the object resting in the hand?
            boolean held = obs.object().position().distance(obs.palm().origin()) < limits.holdDistance();
            finished = finishLoop(held);
            if (!held) {
                status = Status.DROPPED;
            } else {
                beginLoop();
            }
        } else if (sim.time() - loopStart > limits.maxLoopSeconds()) {
            status = Status.TIME_LIMIT;
            finished = finishLoop(false);
        }
        lastPhase = state.phase();
        return finished;
    }

    /** |p - shoulder anchor|, as Vec3.distance computes it. */
    private double distanceFromShoulder(double[] p) {
        Vec3 a = model.joints().get(0).anchor();
        double dx = p[0] - a.x(), dy = p[1] - a.y(), dz = p[2] - a.z();
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    private void beginLoop() {
        loopStart = sim.time();
        apex = Double.NEGATIVE_INFINITY;
        maxDepth = 0;
        maxLimitExcess = 0;
        landing = null;
        loopThrow = loops.isEmpty() ? null : state.currentThrow();
        loopGoal = loops.isEmpty() ? Double.NaN : goals.current();
        if (!loops.isEmpty()) {
            goals.advance(); // the throw of this loop is made: the next one aims at a new goal
        }
        loop.resetPeakTorqueRatio();
    }

    private LoopRecord finishLoop(boolean caught) {
        int index = loops.size();
        LoopRecord r = new LoopRecord(index, caught, index == 0 ? Double.NaN : apex, caught ? null : landing,
                loopGoal, loopThrow, maxDepth, maxLimitExcess, loop.peakTorqueRatio(),
                sim.time() - loopStart);
        loops.add(r);
        return r;
    }
}
