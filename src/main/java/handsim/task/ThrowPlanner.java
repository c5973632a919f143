package handsim.task;

import handsim.config.Json;
import handsim.control.Observation;
import handsim.control.ThrowParameters;
import handsim.control.ThrowSpace;
import handsim.math.Vec3;
import handsim.sim.SimulationDiverged;
import java.util.SplittableRandom;

/**
 * Chooses each throw by trying it first in a twin world: a sampling planner on top of a throw
 * policy, in the spirit of sampling-based character control (not part of the paper). When the
 * live episode is about to throw, its whole state is copied into a twin episode ({@link
 * CatchThrowEpisode#checkpoint}); there the policy's throw and random variations of it are each
 * played out through the flight, the catch and MIDDLE, up to the next throw; the live hand then
 * makes the best of them. The twin steps on bit for bit as the live world would, so the live
 * throw does exactly what it did in the twin.
 *
 * <p>What the live world sees is an ordinary throw: the planner only chooses the seven THROW
 * parameters, and the object is moved by gravity, damping and contacts alone. What it costs is
 * the simulation of the tries (each about 1.5 s of simulated time).
 *
 * <p>A try is better when the task counts its throw a success; among successes, when the long
 * object then lies across the palm, along the palm's z axis (where the next throw succeeds most
 * often; docs/flip-experiments.md, twelfth session); among failures, by the task's reward. The
 * search stops at the first success whose object lies across within {@code goodAlignment}; when
 * none of the tries succeeded, it goes on with wider variations.
 */
public final class ThrowPlanner {

    /**
     * {@code configs/planner.json}.
     *
     * @param candidates throws tried at most per decision, the policy's own first
     * @param spread standard deviation of the variations, in the policy's action units ([-1, 1] per entry)
     * @param goodAlignment |long axis . palm z| after the catch at which a successful try ends the search
     * @param widerCandidates when none of the first tries succeeded, this many more, varied by {@code widerSpread}
     */
    public record Config(int candidates, double spread, double goodAlignment, int widerCandidates, double widerSpread) {

        public static Config parse(Json j) {
            j.allow("comment");
            Config c = new Config(j.integer("candidates", 1, 10000), j.number("spread", 0, 2), j.number("goodAlignment", 0, 1),
                    j.integer("widerCandidates", 0, 10000), j.number("widerSpread", 0, 2));
            j.requireNoUnknownFields();
            return c;
        }
    }

    /** The planner's work so far: decisions, tries, and decisions where no try succeeded. */
    /**
     * The planner's work so far: decisions, tries, decisions where no try succeeded, and live
     * throws whose loop differed in any way from the chosen try's (0 while the twin steps on bit for bit).
     */
    public record Stats(int decisions, int tries, int unsolved, int mispredicted) {

        Stats plus(Stats o) {
            return new Stats(decisions + o.decisions, tries + o.tries, unsolved + o.unsolved, mispredicted + o.mispredicted);
        }
    }

    /** One throw played out in the twin, and the loop it made there (null if it diverged). */
    private record Trial(ThrowParameters parameters, boolean success, double reward, double alignment, LoopRecord loop) {

        boolean betterThan(Trial o) {
            if (success != o.success) {
                return success;
            }
            return success ? alignment > o.alignment : reward > o.reward;
        }
    }

    private final Config config;
    private final ThrowTask task;
    private final ThrowSpace space;
    private final CatchThrowEpisode twin;
    private final ChosenThrow twinThrow;
    private int decisions;
    private int tries;
    private int unsolved;
    private int mispredicted;
    /** The loop the last chosen throw made in the twin, until {@link #check}ed against the live one. */
    private LoopRecord expected;

    /**
     * @param twin an episode in a world of its own (its own engine, {@code IsolatedEngine}), with
     *     the live episode's model, controller settings and object, whose controller throws what
     *     {@code twinThrow} holds
     * @param task the task whose success counts; its goal must not change from throw to throw
     */
    ThrowPlanner(Config config, ThrowTask task, ThrowSpace space, CatchThrowEpisode twin, ChosenThrow twinThrow) {
        requirePlannable(task);
        this.config = config;
        this.task = task;
        this.space = space;
        this.twin = twin;
        this.twinThrow = twinThrow;
    }

    /** The twin episode is restored without the task's goal, so the planner plans for tasks whose goal never changes. */
    static void requirePlannable(ThrowTask task) {
        if (task.goalSize() != 0) {
            throw new IllegalArgumentException("the throw planner needs a task whose goal stays the same from throw to throw "
                    + "(flip); the " + task.name() + " task's changes");
        }
    }

    public Stats stats() {
        return new Stats(decisions, tries, unsolved, mispredicted);
    }

    /**
     * The throw {@code live} should make now; it must be waiting for one ({@link
     * CatchThrowEpisode#runUntilThrowDue}). {@code proposal} is the policy's; {@code seed} seeds the
     * variations (the same seed and state give the same choice).
     */
    public ThrowParameters choose(CatchThrowEpisode live, ThrowParameters proposal, long seed) {
        CatchThrowEpisode.Checkpoint now = live.checkpoint();
        SplittableRandom rng = new SplittableRandom(seed);
        double[] centre = space.toAction(proposal);
        Trial best = null;
        for (int k = 0; k < config.candidates() + config.widerCandidates(); k++) {
            boolean wider = k >= config.candidates();
            if (wider && best.success()) {
                break;
            }
            double spread = wider ? config.widerSpread() : config.spread();
            ThrowParameters candidate = k == 0 ? proposal : space.fromAction(vary(centre, spread, rng));
            Trial t = play(now, candidate);
            tries++;
            if (best == null || t.betterThan(best)) {
                best = t;
            }
            if (best.success() && best.alignment() >= config.goodAlignment()) {
                break;
            }
        }
        decisions++;
        if (!best.success()) {
            unsolved++;
        }
        if (live.sim().captureState().randomSeed() != now.world().randomSeed()) {
            throw new IllegalStateException("the twin world shares the live world's engine: give it one of its own (IsolatedEngine)");
        }
        expected = best.loop();
        return best.parameters();
    }

    /** Compares the loop the live episode made with the chosen throw to the one it made in the twin. */
    public void check(LoopRecord made) {
        if (expected != null && !expected.equals(made)) {
            mispredicted++;
        }
        expected = null;
    }

    private static double[] vary(double[] centre, double spread, SplittableRandom rng) {
        double[] a = centre.clone();
        for (int i = 0; i < a.length; i++) {
            a[i] += spread * gaussian(rng);
        }
        return a;
    }

    private static double gaussian(SplittableRandom rng) {
        return Math.sqrt(-2 * Math.log(1 - rng.nextDouble())) * Math.cos(2 * Math.PI * rng.nextDouble());
    }

    /** Plays {@code candidate} out in the twin, from {@code from} to the next throw or the end of the episode. */
    private Trial play(CatchThrowEpisode.Checkpoint from, ThrowParameters candidate) {
        twin.restore(from);
        twinThrow.set(candidate);
        Observation next;
        try {
            twin.resume();
            next = twin.runUntilThrowDue();
        } catch (SimulationDiverged e) {
            return new Trial(candidate, false, Double.NEGATIVE_INFINITY, 0, null);
        }
        if (twin.loops().size() <= from.loopCount()) {
            return new Trial(candidate, false, Double.NEGATIVE_INFINITY, 0, null);
        }
        LoopRecord made = twin.loops().get(from.loopCount());
        boolean success = next != null && task.success(made);
        return new Trial(candidate, success, task.reward(made), next == null ? 0 : alignment(next), made);
    }

    /** |long axis . palm z| (1 for an object without a long axis): 1 when the object lies across the palm. */
    private double alignment(Observation obs) {
        var axis = twin.sim().objectSpec().longAxis();
        if (axis.isEmpty()) {
            return 1;
        }
        Vec3 a = obs.object().orientation().rotate(axis.get());
        return Math.abs(a.dot(obs.palm().rotation().zAxis()));
    }
}
