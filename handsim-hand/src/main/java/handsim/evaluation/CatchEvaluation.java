package handsim.evaluation;

import handsim.planning.PlannerConfig;
import handsim.planning.ThrowPlanner;
import handsim.task.CatchThrowEpisode;
import handsim.task.EpisodeLimits;
import handsim.task.EpisodeResult;
import handsim.task.LaunchDistribution;
import handsim.task.LoopRecord;
import handsim.task.ThrowTask;

import handsim.control.ControllerConfig;
import handsim.control.NominalController;
import handsim.control.Observation;
import handsim.control.PdController;
import handsim.control.ThrowDecision;
import handsim.control.ThrowPolicy;
import handsim.math.Vec3;
import handsim.sim.ObjectSpec;
import handsim.sim.RigidState;
import handsim.sim.SimulationDiverged;
import handsim.sim.Simulator;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Seeded catch-and-throw episodes of a task: each seed draws the object's size and mass within
 * its tolerance and a launch from the {@link LaunchDistribution}, sets up the task's episode
 * (its goals, the box), then runs loops until a drop or {@code maxLoops} throws. The same seed
 * always gives the same episode. Holds the task's episode state: one evaluation per thread.
 */
public final class CatchEvaluation {

    /** Called after every finished loop. */
    @FunctionalInterface
    public interface LoopListener {
        void onLoop(long seed, LoopRecord loop);
    }

    /**
     * Told after every tick with the simulator: a watcher (an animation export) reads the world
     * and never changes it.
     */
    @FunctionalInterface
    public interface TickWatcher {
        void afterTick(Simulator sim);
    }

    /**
     * The throw policy of episodes whose every throw is decided by their caller ({@link
     * CatchThrowEpisode#decide}): a learner's environment, a teacher's twin.
     */
    public static final ThrowPolicy DECIDED_BY_CALLER = obs -> {
        throw new IllegalStateException("every throw of these episodes is decided by their caller (CatchThrowEpisode.decide)");
    };

    private final ControllerConfig controllerConfig;
    private final EpisodeLimits limits;
    private final LaunchDistribution launches;
    private final ObjectSpec object;
    private final ThrowPolicy throwPolicy;
    private final ThrowTask task;
    /** Non-null when every throw is planned in a twin world ({@link #planned}). */
    private PlannerConfig planning;
    private Simulator twin;
    /** The planner's work in the episodes before the running one. */
    private ThrowPlanner.Stats earlierEpisodes = ThrowPlanner.Stats.NONE;
    /** The running episode's planner; null without planning. */
    private ThrowPlanner planner;
    /** The index of the loop whose throw was planned last (checked against the twin's when it ends). */
    private int plannedLoop = -1;
    private TickWatcher watcher;

    /** {@code throwPolicy} chooses the throws for {@code task}'s goals. */
    public CatchEvaluation(ControllerConfig controllerConfig, EpisodeLimits limits, LaunchDistribution launches,
            ObjectSpec object, ThrowTask task, ThrowPolicy throwPolicy) {
        this.task = task;
        this.controllerConfig = task.controller(controllerConfig);
        this.limits = limits;
        this.launches = launches;
        this.object = object;
        this.throwPolicy = throwPolicy;
    }

    /** Evaluation of the nominal controller: every throw is the task's hand-tuned one for its goal. */
    public static CatchEvaluation nominal(ControllerConfig controllerConfig, EpisodeLimits limits,
            LaunchDistribution launches, ObjectSpec object, ThrowTask task) {
        return new CatchEvaluation(controllerConfig, limits, launches, object, task, obs -> task.nominalThrow());
    }

    /**
     * This evaluation with every throw chosen by a {@link ThrowPlanner}: the throw policy proposes,
     * the planner tries its throw and variations of it in {@code twin}, a simulator of the same
     * model and config with an engine of its own, and the hand makes the best. The caller closes
     * {@code twin}.
     */
    public CatchEvaluation planned(PlannerConfig config, Simulator twin) {
        task.requireFixedGoal("throw planner");
        CatchEvaluation e = new CatchEvaluation(controllerConfig, limits, launches, object, task, throwPolicy);
        e.planning = config;
        e.twin = twin;
        e.watcher = watcher;
        return e;
    }

    /** This evaluation with {@code w} told after every tick of its episodes (null: none). */
    public CatchEvaluation watchedBy(TickWatcher w) {
        watcher = w;
        return this;
    }

    /** Whether every throw is chosen by a planner ({@link #planned}). */
    public boolean isPlanned() {
        return planning != null;
    }

    /** What the planner did over every episode so far (zeros without planning). */
    public ThrowPlanner.Stats plannerStats() {
        return planner == null ? earlierEpisodes : earlierEpisodes.plus(planner.stats());
    }

    /** What the planner did in the running episode, or the last one (zeros without planning). */
    public ThrowPlanner.Stats episodePlannerStats() {
        return planner == null ? ThrowPlanner.Stats.NONE : planner.stats();
    }

    /** The task whose goals the throws aim at (its episode state is shared by every episode this evaluation starts). */
    public ThrowTask task() {
        return task;
    }

    /** When its episodes' objects count as caught or dropped, and how runs of episodes behave. */
    public EpisodeLimits limits() {
        return limits;
    }

    /** The object thrown, before a seed varies it within its tolerance. */
    public ObjectSpec object() {
        return object;
    }

    /** Runs the episode of {@code seed} on {@code sim} (which it resets). */
    public EpisodeResult run(Simulator sim, long seed, int maxLoops, LoopListener listener) {
        return run(sim, seed, Vec3.ZERO, maxLoops, listener);
    }

    /** {@link #run} with the launch velocity nudged by {@code launchNudge} (m/s). */
    public EpisodeResult run(Simulator sim, long seed, Vec3 launchNudge, int maxLoops, LoopListener listener) {
        CatchThrowEpisode episode = start(sim, seed, launchNudge);
        while (episode.status() == CatchThrowEpisode.Status.RUNNING && episode.loops().size() <= maxLoops) {
            LoopRecord r = tick(episode, seed);
            if (r != null && listener != null) {
                listener.onLoop(seed, r);
            }
        }
        return episode.result(seed);
    }

    /**
     * One tick of an episode this evaluation started; returns the loop record finished in it, or
     * null. With planning, a tick at a throw's decision chooses the throw ({@link ThrowPlanner})
     * and begins it (the throw-in's catch was chosen at the start). A divergence names the episode's seed and loop, so the run that failed can
     * be replayed.
     */
    public LoopRecord tick(CatchThrowEpisode episode, long seed) {
        LoopRecord r = tickOnce(episode, seed);
        if (watcher != null) {
            watcher.afterTick(episode.sim());
        }
        return r;
    }

    private LoopRecord tickOnce(CatchThrowEpisode episode, long seed) {
        try {
            if (episode.decision() != null) {
                decide(episode, seed); // a planned throw is chosen in a tick of its own
                return null;
            }
            LoopRecord r = episode.tick();
            if (planner == null && episode.decision() != null) {
                decide(episode, seed); // the throw is decided in the same tick as the catch is judged
            } else if (r != null && r.index() == plannedLoop) {
                planner.check(r);
            }
            return r;
        } catch (SimulationDiverged e) {
            throw new SimulationDiverged("episode of seed " + seed + ", loop " + episode.loops().size() + ": " + e.getMessage());
        }
    }

    /** The throw {@code episode} waits at, decided by the throw policy or, with planning, by the planner. */
    private void decide(CatchThrowEpisode episode, long seed) {
        Observation at = episode.decision();
        if (planner == null) {
            episode.decide(ThrowDecision.of(throwPolicy.decide(at, episode.loops().size())));
            return;
        }
        plannedLoop = episode.loops().size();
        long variations = seed ^ 0x9E3779B97F4A7C15L * plannedLoop;
        episode.decide(planner.choose(episode, throwPolicy, variations));
    }

    /**
     * Runs the episode of {@code seed} until a throw fails the task ({@link ThrowTask#success})
     * or {@code maxThrows} throws succeeded in a row: the loops up to and including the first
     * failure (a dropped throw-in ends it before any throw).
     */
    public List<LoopRecord> runWhileSuccessful(Simulator sim, long seed, int maxThrows) {
        return runWhileSuccessful(sim, seed, maxThrows, null);
    }

    /** {@link #runWhileSuccessful} telling {@code listener} (if not null) of every loop as it ends. */
    public List<LoopRecord> runWhileSuccessful(Simulator sim, long seed, int maxThrows, LoopListener listener) {
        CatchThrowEpisode episode = start(sim, seed);
        int inARow = 0;
        while (episode.status() == CatchThrowEpisode.Status.RUNNING && inARow < maxThrows) {
            LoopRecord r = tick(episode, seed);
            if (r == null) {
                continue;
            }
            if (listener != null) {
                listener.onLoop(seed, r);
            }
            if (r.index() == 0 ? !r.caught() : !task.success(r)) {
                break;
            }
            inARow += r.index() == 0 ? 0 : 1;
        }
        return List.copyOf(episode.loops());
    }

    /** Throws in a row at the start of {@code loops} that did what the task asks. */
    public int successesInARow(List<LoopRecord> loops) {
        int n = 0;
        for (LoopRecord r : loops) {
            if (r.index() > 0) {
                if (!task.success(r)) {
                    break;
                }
                n++;
            }
        }
        return n;
    }

    /** Resets {@code sim} and starts the episode of {@code seed}: the object is in the air, nothing ticked yet. */
    public CatchThrowEpisode start(Simulator sim, long seed) {
        return start(sim, seed, Vec3.ZERO);
    }

    /**
     * The episode of {@code seed} with {@code launchNudge} (m/s) added to the launch velocity:
     * how far a tiny difference carries through the loops ({@link LaunchSensitivity}).
     */
    public CatchThrowEpisode start(Simulator sim, long seed, Vec3 launchNudge) {
        SplittableRandom rng = new SplittableRandom(seed);
        ObjectSpec thrown = object.randomized(rng);
        NominalController controller = new NominalController(sim.model(), controllerConfig, thrown, sim.config().gravity());
        RigidState sampled = launches.sample(rng, controller.neutralPalm().origin(), controllerConfig.interceptionHeight(),
                thrown, sim.config().gravity());
        RigidState launch = launchNudge.equals(Vec3.ZERO) ? sampled
                : new RigidState(sampled.position(), sampled.orientation(), sampled.velocity().plus(launchNudge), sampled.angularVelocity());
        CatchThrowEpisode episode = new CatchThrowEpisode(sim, new PdController(sim.model(), controllerConfig.pd()),
                controller, task, limits);
        if (planning != null) {
            newPlanner(episode);
        }
        episode.start(thrown, launch, seed);
        if (planner != null) {
            episode.catchThrowInAs(planner.chooseThrowInCatch(episode, throwPolicy, seed));
            plannedLoop = 0;
        }
        return episode;
    }

    /** A planner of its own for {@code live}, an episode not yet started, with its twin episode. */
    private void newPlanner(CatchThrowEpisode live) {
        if (planner != null) {
            earlierEpisodes = earlierEpisodes.plus(planner.stats());
        }
        planner = new ThrowPlanner(planning, task, task.throwSpace(controllerConfig.throwSpace()), live.twinOn(twin));
        plannedLoop = -1;
    }
}
