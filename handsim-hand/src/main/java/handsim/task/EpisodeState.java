package handsim.task;

import handsim.control.ControllerState;
import handsim.control.Observation;
import handsim.control.ThrowParameters;
import handsim.math.Vec3;
import java.util.ArrayList;
import java.util.List;

/**
 * Everything a {@link CatchThrowEpisode} holds beside its world: the controller's state, the
 * loops finished so far, how the episode stands, the hand contacts since the last tick, the
 * decision it waits at, the flight being followed and the statistics of the loop in progress.
 * A checkpoint is a world state and one of these ({@link CatchThrowEpisode.Checkpoint}); {@link
 * #copy} is the one place where it is copied, so a twin episode continues every field.
 */
public final class EpisodeState {

    ControllerState controller;
    final List<LoopRecord> loops;
    CatchThrowEpisode.Status status = CatchThrowEpisode.Status.RUNNING;
    /** The hand bodies that touched the object since the last tick (bit mask). */
    long touchedSinceTick;
    /** The observation the episode stopped at to decide a throw on; null when not at a decision. */
    Observation decision;
    final FlightTracker flight;
    LoopStats loop = new LoopStats();

    EpisodeState(ControllerState controller, FlightTracker flight) {
        this(controller, new ArrayList<>(), flight);
    }

    private EpisodeState(ControllerState controller, List<LoopRecord> loops, FlightTracker flight) {
        this.controller = controller;
        this.loops = loops;
        this.flight = flight;
    }

    /** An independent state equal to this one in every field. */
    public EpisodeState copy() {
        EpisodeState c = new EpisodeState(controller.copy(), new ArrayList<>(loops), flight.copy());
        c.status = status;
        c.touchedSinceTick = touchedSinceTick;
        c.decision = decision;
        c.loop = loop.copy();
        return c;
    }

    public ControllerState controller() {
        return controller;
    }

    /** Finished loops, in order. */
    public List<LoopRecord> loops() {
        return loops;
    }

    public CatchThrowEpisode.Status status() {
        return status;
    }

    /** The observation a throw is to be decided on, or null when the episode is not at a decision. */
    public Observation decision() {
        return decision;
    }

    /** The statistics of the loop in progress, from its throw (or the launch) to its catch. */
    static final class LoopStats {
        double loopStart;
        double apex = Double.NEGATIVE_INFINITY;
        double maxDepth;
        double maxLimitExcess;
        double peakTorqueRatio;
        boolean boxHit;
        double boxDistance = Double.POSITIVE_INFINITY;
        Vec3 landing;
        /** The judged catch's tilt of the long axis out of the palm plane (see {@link LoopRecord#catchTilt}). */
        double catchTilt = Double.NaN;
        /** The judged catch's heading of the long axis in the palm (see {@link LoopRecord#catchHeading}). */
        double catchHeading = Double.NaN;
        ThrowParameters loopThrow;
        double loopGoal = Double.NaN;

        LoopStats copy() {
            LoopStats c = new LoopStats();
            c.loopStart = loopStart;
            c.apex = apex;
            c.maxDepth = maxDepth;
            c.maxLimitExcess = maxLimitExcess;
            c.peakTorqueRatio = peakTorqueRatio;
            c.boxHit = boxHit;
            c.boxDistance = boxDistance;
            c.landing = landing;
            c.catchTilt = catchTilt;
            c.catchHeading = catchHeading;
            c.loopThrow = loopThrow;
            c.loopGoal = loopGoal;
            return c;
        }
    }
}
