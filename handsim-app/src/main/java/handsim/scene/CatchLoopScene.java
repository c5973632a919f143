package handsim.scene;

import handsim.control.Phase;
import handsim.evaluation.CatchEvaluation;
import handsim.math.Vec3;
import handsim.planning.ThrowPlanner;
import handsim.sim.SimulationDiverged;
import handsim.sim.Simulator;
import handsim.sim.WorldSnapshot;
import handsim.task.CatchThrowEpisode;
import handsim.task.EpisodeLimits;
import handsim.task.Goal;
import handsim.task.LoopRecord;
import handsim.task.ThrowTask;
import handsim.taskdef.SteeredTask;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;

/**
 * A task for watching: endless catch-and-throw, running the episodes of a {@link
 * CatchEvaluation} one after another. When an episode ends (a drop, a time limit, or a diverged
 * simulation) the world is reset and the next seed's object is thrown in; the status says so.
 * After {@link EpisodeLimits#maxFailedThrowIns} episodes in a row whose throw-in was not caught
 * it stops and says why (R or N starts it again). The goal (the height, the box) can be moved
 * while it runs.
 */
public final class CatchLoopScene implements InteractiveScene {

    private final Simulator sim;
    /** Closed with the scene besides {@link #sim} (a planner's twin world), or null. */
    private final AutoCloseable alsoOwned;
    private final CatchEvaluation evaluation;
    /** The evaluation's task with its goal's drawing and steering. */
    private final SteeredTask steered;
    private final HeightControl heightControl;
    private CatchThrowEpisode episode;
    private long seed;
    private int episodes = 1;
    private int catchesInARow;
    private int bestInARow;
    private LoopRecord lastThrow;
    private String lastEvent = "thrown in";
    /** Episodes in a row whose throw-in was not caught. */
    private int failedThrowIns;
    /** Why the scene stopped throwing objects in, or null while it runs. */
    private String stopped;

    /**
     * Owns {@code sim} (closed with the scene) and {@code alsoOwned} (the twin world of a {@link
     * CatchEvaluation#planned} evaluation, or null), and starts the episode of {@code seed};
     * {@code steered} is the evaluation's task with its goal's hooks.
     */
    public CatchLoopScene(Simulator sim, CatchEvaluation evaluation, SteeredTask steered, long seed, HeightControl heightControl,
            AutoCloseable alsoOwned) {
        if (steered.task() != evaluation.task()) {
            throw new IllegalArgumentException("the scene steers another task than its evaluation runs");
        }
        this.sim = sim;
        this.alsoOwned = alsoOwned;
        this.evaluation = evaluation;
        this.steered = steered;
        this.heightControl = heightControl;
        this.seed = seed;
        this.episode = evaluation.start(sim, seed);
    }

    @Override
    public void advance(double seconds) {
        if (stopped != null) {
            return; // nothing is thrown in any more: the world stands still until R or N
        }
        double until = sim.time() + seconds;
        while (sim.time() < until - 1e-12) {
            if (episode.status() != CatchThrowEpisode.Status.RUNNING) {
                restart(episode.status() == CatchThrowEpisode.Status.DROPPED ? "dropped: new throw" : "time limit: new throw");
                return;
            }
            LoopRecord r;
            try {
                r = evaluation.tick(episode, seed);
            } catch (SimulationDiverged e) {
                restart("simulation diverged (" + e.getMessage() + "): new throw");
                return;
            }
            if (r != null) {
                record(r);
            }
        }
    }

    private void record(LoopRecord r) {
        if (r.caught()) {
            catchesInARow++;
            bestInARow = Math.max(bestInARow, catchesInARow);
        } else {
            catchesInARow = 0;
        }
        if (r.index() > 0) {
            lastThrow = r;
        }
        lastEvent = r.caught() ? (r.index() == 0 ? "caught the throw-in" : "caught") : "dropped";
    }

    /** Ends the episode and throws the next seed's object in, unless too many throw-ins in a row failed. */
    private void restart(String event) {
        lastEvent = event;
        catchesInARow = 0;
        boolean caughtIn = !episode.loops().isEmpty() && episode.loops().get(0).caught();
        failedThrowIns = caughtIn ? 0 : failedThrowIns + 1;
        if (failedThrowIns >= evaluation.limits().maxFailedThrowIns()) {
            stopped = String.format(Locale.ROOT, "stopped: %d throw-ins in a row were not caught (seeds %d-%d; "
                    + "configs/episode.json maxFailedThrowIns); R or N tries again", failedThrowIns, seed - failedThrowIns + 1, seed);
            lastEvent = stopped;
            return;
        }
        episodes++;
        seed++;
        episode = evaluation.start(sim, seed);
    }

    @Override
    public String apply(SceneCommand command) {
        double step = heightControl.step();
        switch (command) {
            case RESET -> {
                resume();
                episode = evaluation.start(sim, seed);
                catchesInARow = 0;
                lastEvent = "reset";
                return "reset: episode of seed " + seed + " from the start";
            }
            case NEW_THROW -> {
                resume();
                restart("new throw");
                return "new throw: episode of seed " + seed;
            }
            case GOAL_UP -> {
                return steered.moveGoal().apply(new Vec3(0, step, 0));
            }
            case GOAL_DOWN -> {
                return steered.moveGoal().apply(new Vec3(0, -step, 0));
            }
            case GOAL_LEFT -> {
                return steered.moveGoal().apply(new Vec3(-step, 0, 0));
            }
            case GOAL_RIGHT -> {
                return steered.moveGoal().apply(new Vec3(step, 0, 0));
            }
            case GOAL_NEARER -> {
                return steered.moveGoal().apply(new Vec3(0, 0, -step));
            }
            case GOAL_FARTHER -> {
                return steered.moveGoal().apply(new Vec3(0, 0, step));
            }
            default -> {
                return command + " is not something this scene can do";
            }
        }
    }

    /**
     * The task's goal; for the height task the throw in the air shows the height it aims at,
     * while the object rests in the hand (MIDDLE) and before the first throw the next throw's.
     */
    @Override
    public Goal goal() {
        Goal g = steered.goal().get();
        double inFlight = episode.throwGoal();
        if (g instanceof Goal.Height h && !Double.isNaN(inFlight) && episode.controllerState().phase() != Phase.MIDDLE) {
            return new Goal.Height(inFlight, h.center());
        }
        return g;
    }

    @Override
    public double time() {
        return sim.time();
    }

    @Override
    public WorldSnapshot snapshot() {
        return sim.snapshot();
    }

    /** The episode being run now. */
    public CatchThrowEpisode episode() {
        return episode;
    }

    /** After a stop, a command from the person watching starts the throw-ins again. */
    private void resume() {
        stopped = null;
        failedThrowIns = 0;
    }

    @Override
    public Map<String, String> status() {
        Map<String, String> s = new LinkedHashMap<>();
        if (stopped != null) {
            s.put("stopped", stopped);
        }
        s.put("state", episode.controllerState().phase().name());
        // loop 0 catches the throw-in, loop k >= 1 is the k-th throw and its catch
        s.put("loop", Integer.toString(episode.loops().size()));
        s.put("catches in a row", catchesInARow + " (best " + bestInARow + ")");
        ThrowTask task = evaluation.task();
        s.put("task", task.name());
        if (goal() instanceof Goal.Height h) {
            s.put("last apex", lastThrow == null ? "-" : String.format(Locale.ROOT, "%.3f m (goal %.3f, %+.3f)",
                    lastThrow.apexHeight(), lastThrow.targetHeight(), lastThrow.apexHeight() - lastThrow.targetHeight()));
            double next = task.targetHeight();
            s.put("goal", Math.abs(h.height() - next) > 5e-4 ? String.format(Locale.ROOT, "%.3f m (next %.3f m)", h.height(), next)
                    : String.format(Locale.ROOT, "%.3f m", h.height()));
        } else if (goal() instanceof Goal.Box b) {
            s.put("box", String.format(Locale.ROOT, "(%.2f, %.2f, %.2f) m", b.center().x(), b.center().y(), b.center().z()));
            s.put("last hit", lastThrow == null ? "-" : lastThrow.boxHit() ? "hit" : String.format(Locale.ROOT, "missed by %.3f m",
                    lastThrow.boxDistance()));
        }
        if (lastThrow != null && !Double.isNaN(lastThrow.flightRotation())) {
            String arrival = Double.isNaN(lastThrow.arrivalTilt()) ? ""
                    : String.format(Locale.ROOT, ", came back %.0f deg out of the horizontal", Math.toDegrees(lastThrow.arrivalTilt()));
            s.put("last turn", String.format(Locale.ROOT, "%.0f deg in flight", Math.toDegrees(lastThrow.flightRotation())) + arrival);
        }
        if (evaluation.isPlanned()) {
            ThrowPlanner.Stats p = evaluation.plannerStats();
            s.put("planner", String.format(Locale.ROOT, "%d throws chosen from %d tries in a twin world, %d with no successful try",
                    p.decisions(), p.tries(), p.unsolved()));
        }
        s.put("last", lastEvent);
        s.put("episode", "seed " + seed + " (" + episodes + " so far)");
        s.put("t", String.format(Locale.ROOT, "%.2f s", sim.time()));
        return s;
    }

    @Override
    public void close() {
        sim.close();
        if (alsoOwned != null) {
            try {
                alsoOwned.close();
            } catch (Exception e) {
                throw new IllegalStateException("cannot close the planner's twin world", e);
            }
        }
    }
}
