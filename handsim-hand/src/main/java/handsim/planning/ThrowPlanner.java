package handsim.planning;

import handsim.task.CatchThrowEpisode;
import handsim.task.LoopRecord;
import handsim.task.ThrowTask;

import handsim.control.CatchStyle;
import handsim.control.Observation;
import handsim.control.ThrowDecision;
import handsim.control.ThrowParameters;
import handsim.control.ThrowPolicy;
import handsim.control.ThrowSpace;
import handsim.math.Vec3;
import java.util.ArrayList;
import java.util.List;
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
 * parameters and, when it has catch styles, how the catch after the throw meets the object (the
 * interception plane's height and the palm's speed there, {@link CatchStyle}); the object is moved
 * by gravity, damping and contacts alone. What it costs is
 * the simulation of the tries (each about 1.5 s of simulated time).
 *
 * <p>A try is better when the task counts its throw a success; with a lookahead, when a throw
 * from the state it leads to succeeds too (no dead end; that throw is then tried first at the next
 * decision, so the search there cannot miss it); then, among successes, when the long
 * object lies across the palm, along the palm's z axis (where the next throw succeeds most often;
 * docs/experiments.md, "Planner"); among failures, by the task's reward. The search
 * stops at the first such success lying across within {@code goodAlignment}; when none of a
 * round's tries was one, the next round goes on with its own spread (an object may have rounds of
 * its own: the club's are many and narrow, docs/club.md, "Planner").
 *
 * <p>Before an episode's first tick the planner may likewise choose how the hand catches the
 * throw-in ({@link #chooseThrowInCatch}): only the catch, the launch is the episode's.
 */
public final class ThrowPlanner {

    /**
     * The planner's work so far: throw decisions, tries (the lookahead's and the throw-in's
     * included), decisions where no try succeeded, live loops whose record differed in any way
     * from the chosen try's (0 while the twin steps on bit for bit; a promised throw that failed
     * counts too), decisions that began with the throw the lookahead had found to succeed from
     * their state (promised), decisions whose throw is caught otherwise than the controller's own
     * way, throw-ins caught otherwise, and catches played again from a tried throw's end with
     * another style ({@link PlannerConfig#catchBranches}; counted among the tries too).
     */
    public record Stats(int decisions, int tries, int unsolved, int mispredicted, int promised, int restyledCatches,
            int restyledThrowIns, int branches) {

        public static final Stats NONE = new Stats(0, 0, 0, 0, 0, 0, 0, 0);

        public Stats plus(Stats o) {
            return new Stats(decisions + o.decisions, tries + o.tries, unsolved + o.unsolved, mispredicted + o.mispredicted,
                    promised + o.promised, restyledCatches + o.restyledCatches, restyledThrowIns + o.restyledThrowIns,
                    branches + o.branches);
        }
    }

    /**
     * One throw played out in the twin: whether it succeeded and, with a lookahead, the throw from
     * its next state that succeeded too ({@code next}, null when none did; without a lookahead a
     * success counts as leading on); the loop it made there (null if it diverged).
     */
    private record Trial(Choice choice, boolean success, boolean open, double reward, double alignment,
            LoopRecord loop, Continuation next) {

        static Trial failed(Choice choice) {
            return new Trial(choice, false, false, Double.NEGATIVE_INFINITY, 0, null, null);
        }

        /** A success that leads on: the kind of try the search looks for. */
        boolean good() {
            return success && open;
        }

        boolean betterThan(Trial o) {
            if (success != o.success) {
                return success;
            }
            if (open != o.open) {
                return open;
            }
            return success ? alignment > o.alignment : reward > o.reward;
        }

        Trial leadingOn(Continuation c) {
            return new Trial(choice, success, c != null, reward, alignment, loop, c);
        }
    }

    /**
     * A throw and how its catch meets the object (null: as the controller's own): what the planner
     * tries (for the throw-in only the catch, the throw null).
     */
    private record Choice(ThrowParameters throwing, CatchStyle catching) {

        ThrowDecision decision() {
            return new ThrowDecision(throwing, catching);
        }
    }

    /**
     * A choice the lookahead found to succeed from {@code state}, the decision a chosen try leads
     * to; with a deeper lookahead, {@code next}: the one found from the state it leads to (else null).
     */
    private record Continuation(Observation state, Choice choice, Continuation next) {}

    private final PlannerConfig config;
    private final ThrowTask task;
    private final ThrowSpace space;
    private final TwinEpisode twin;
    private int decisions;
    private int tries;
    private int unsolved;
    private int mispredicted;
    private int promisedDecisions;
    private int restyledCatches;
    private int restyledThrowIns;
    private int branches;
    /** Where the last throw {@link #play}ed in the twin ended THROW (with catch branches only), or null. */
    private CatchThrowEpisode.Checkpoint throwEnd;
    /** The loop the last chosen throw made in the twin, until {@link #check}ed against the live one. */
    private LoopRecord expected;
    /** The lookahead's successful throw from the state the last chosen throw leads to, tried first there. */
    private Continuation promised;

    /**
     * @param twin an episode in a world of its own (its own engine, {@code IsolatedEngine}), with
     *     the live episode's model, controller settings and object ({@link CatchThrowEpisode#twinOn})
     * @param task the task whose success counts; its goal must not change from throw to throw
     */
    public ThrowPlanner(PlannerConfig config, ThrowTask task, ThrowSpace space, CatchThrowEpisode twin) {
        task.requireFixedGoal("throw planner");
        this.config = config;
        this.task = task;
        this.space = space;
        this.twin = new TwinEpisode(twin);
    }

    public Stats stats() {
        return new Stats(decisions, tries, unsolved, mispredicted, promisedDecisions, restyledCatches, restyledThrowIns,
                branches);
    }

    /**
     * The throw {@code live} should make now; it must be at a decision ({@link
     * CatchThrowEpisode#advanceToDecision}). {@code policy} proposes the first try (and, with a
     * lookahead, the first from each next state); {@code seed} seeds the variations (the same
     * seed and state give the same choice).
     */
    public ThrowDecision choose(CatchThrowEpisode live, ThrowPolicy policy, long seed) {
        CatchThrowEpisode.Checkpoint now = live.checkpoint();
        SplittableRandom rng = new SplittableRandom(seed);
        ThrowParameters proposal = policy.decide(live.decision(), live.loops().size());
        double[] centre = space.toAction(proposal);
        Trial best = null;
        if (promised != null && promised.state().sameValues(live.decision())) {
            promisedDecisions++;
            best = judge(play(now, promised.choice()), policy, rng, config.depth(), promised.next());
            if (!best.success()) {
                mispredicted++; // the twin had shown this throw succeed from this very state
            }
        }
        promised = null;
        int k = 0;
        search:
        for (int round = 0; round < config.rounds().size(); round++) {
            if (best != null && best.good() && (round > 0 || best.alignment() >= config.goodAlignment())) {
                break;
            }
            PlannerConfig.Round r = config.rounds().get(round);
            for (int c = 0; c < r.candidates(); c++, k++) {
                ThrowParameters candidate = k == 0 ? proposal : space.fromAction(TwinEpisode.vary(centre, r.spread(), rng));
                CatchStyle catching = r.catchStyles().isEmpty() ? config.catchStyle(k)
                        : r.catchStyles().get(c % r.catchStyles().size());
                Trial t = tryThrow(now, new Choice(candidate, catching), policy, rng, config.depth());
                if (best == null || t.betterThan(best)) {
                    best = t;
                }
                if (best.good() && best.alignment() >= config.goodAlignment()) {
                    break search;
                }
            }
        }
        decisions++;
        if (!best.success()) {
            unsolved++;
        }
        if (best.choice().catching() != null) {
            restyledCatches++;
        }
        if (live.sim().captureState().randomSeed() != now.world().randomSeed()) {
            throw new IllegalStateException("the twin world shares the live world's engine: give it one of its own (IsolatedEngine)");
        }
        expected = best.loop();
        promised = best.next();
        return best.choice().decision();
    }

    /**
     * How {@code live}, started and not yet ticked, should catch its throw-in: the controller's own
     * way and then each of the config's throw-in styles are played out in the twin up to the first
     * throw's decision, until one holds the object and, with a lookahead, a throw from there
     * succeeds (that throw is then tried first at the decision). Otherwise the best as {@link
     * Trial#betterThan} ranks them, the earliest among equals. Null: the controller's own way,
     * also when the config has no throw-in styles (nothing is tried then).
     */
    public CatchStyle chooseThrowInCatch(CatchThrowEpisode live, ThrowPolicy policy, long seed) {
        promised = null;
        if (config.throwInStyles().isEmpty()) {
            return null;
        }
        CatchThrowEpisode.Checkpoint start = live.checkpoint();
        SplittableRandom rng = new SplittableRandom(seed);
        List<CatchStyle> styles = new ArrayList<>();
        styles.add(null);
        styles.addAll(config.throwInStyles());
        Trial best = null;
        for (CatchStyle style : styles) {
            Trial t = judge(playThrowIn(start, style), policy, rng, config.depth(), null);
            if (best == null || t.betterThan(best)) {
                best = t;
            }
            if (best.good()) {
                break;
            }
        }
        if (best.choice().catching() != null) {
            restyledThrowIns++;
        }
        expected = best.loop();
        promised = best.next();
        return best.choice().catching();
    }

    /** The throw-in caught as {@code style} says in the twin, up to the first throw's decision: a success if it holds. */
    private Trial playThrowIn(CatchThrowEpisode.Checkpoint start, CatchStyle style) {
        tries++;
        TwinEpisode.Outcome o = twin.playThrowIn(start, style);
        Choice choice = new Choice(null, style);
        if (o.failed()) {
            return Trial.failed(choice);
        }
        boolean held = o.next() != null && o.loop().caught();
        return new Trial(choice, held, held, 0, held ? alignment(o.next()) : 0, o.loop(), null);
    }

    /** Compares the loop the live episode made with the chosen throw to the one it made in the twin. */
    public void check(LoopRecord made) {
        if (expected != null && !expected.equals(made)) {
            mispredicted++;
        }
        expected = null;
    }

    /**
     * Whether a successful try, the twin standing at its next state, leads on: {@code depth}
     * throws in a row from there succeed, each found among up to {@code lookahead} (0: judged as
     * played). {@code hint}: a continuation found before from that state, tried first.
     */
    private Trial judge(Trial t, ThrowPolicy policy, SplittableRandom rng, int depth, Continuation hint) {
        return depth > 0 && t.success() ? t.leadingOn(continuation(policy, rng, depth, hint)) : t;
    }

    /**
     * {@code candidate} played and judged; when it is no success leading on but the task says
     * another catch may matter, its throw's catch is played again from where THROW ended with
     * each of the config's catch branches in turn, until one is: the best of them.
     */
    private Trial tryThrow(CatchThrowEpisode.Checkpoint from, Choice candidate, ThrowPolicy policy, SplittableRandom rng, int depth) {
        Trial played = play(from, candidate);
        CatchThrowEpisode.Checkpoint end = throwEnd; // before the lookahead plays on from the try
        Trial best = judge(played, policy, rng, depth, null);
        if (end == null || best.good() || best.loop() == null || !task.catchMayMatter(best.loop())) {
            return best;
        }
        for (CatchStyle style : config.catchBranches()) {
            if (style.equals(candidate.catching())) {
                continue;
            }
            Trial t = judge(playCatch(end, from.loopCount(), new Choice(candidate.throwing(), style)), policy, rng, depth, null);
            if (t.betterThan(best)) {
                best = t;
            }
            if (best.good()) {
                break;
            }
        }
        return best;
    }

    /**
     * From the twin's state now (a successful try's next decision), a throw that succeeds and
     * leads on {@code depth - 1} throws further, or null: {@code hint} first when it was found from
     * this very state, then the policy's throw and variations by the spread of round 1, up to
     * {@code lookahead} in all.
     */
    private Continuation continuation(ThrowPolicy policy, SplittableRandom rng, int depth, Continuation hint) {
        CatchThrowEpisode.Checkpoint next = twin.episode().checkpoint();
        Observation state = twin.episode().decision();
        if (hint != null && hint.state().sameValues(state)) {
            Trial t = judge(play(next, hint.choice()), policy, rng, depth - 1, hint.next());
            if (t.good()) {
                return new Continuation(state, t.choice(), t.next());
            }
        }
        ThrowParameters proposal = policy.decide(state, twin.episode().loops().size());
        double[] centre = space.toAction(proposal);
        for (int j = 0; j < config.lookahead(); j++) {
            ThrowParameters candidate = j == 0 ? proposal : space.fromAction(TwinEpisode.vary(centre, config.rounds().get(0).spread(), rng));
            Trial t = tryThrow(next, new Choice(candidate, config.catchStyle(j)), policy, rng, depth - 1);
            if (t.good()) {
                return new Continuation(state, t.choice(), t.next());
            }
        }
        return null;
    }

    /**
     * Plays {@code candidate} out in the twin, from {@code from} to the next throw's decision (where
     * the twin then waits) or the end of the episode. Without a lookahead a success counts as open.
     */
    private Trial play(CatchThrowEpisode.Checkpoint from, Choice candidate) {
        tries++;
        TwinEpisode.Outcome o = twin.play(from, candidate.decision(), !config.catchBranches().isEmpty());
        throwEnd = o.throwEnd();
        return played(candidate, o);
    }

    /**
     * The catch of the throw that ended THROW at {@code end} played again from there, meeting the
     * object as {@code candidate} says, to the next throw's decision or the end of the episode.
     */
    private Trial playCatch(CatchThrowEpisode.Checkpoint end, int loopCount, Choice candidate) {
        tries++;
        branches++;
        return played(candidate, twin.playCatch(end, loopCount, candidate.catching()));
    }

    /** The try of {@code candidate} that made {@code o}. */
    private Trial played(Choice candidate, TwinEpisode.Outcome o) {
        if (o.failed()) {
            return Trial.failed(candidate);
        }
        boolean success = o.success(task);
        return new Trial(candidate, success, success, task.reward(o.loop()), o.next() == null ? 0 : alignment(o.next()), o.loop(), null);
    }

    /** |long axis . palm z| (1 for an object without a long axis): 1 when the object lies across the palm. */
    private double alignment(Observation obs) {
        var axis = twin.episode().sim().objectSpec().longAxis();
        if (axis.isEmpty()) {
            return 1;
        }
        Vec3 a = obs.object().orientation().rotate(axis.get());
        return Math.abs(a.dot(obs.palm().rotation().zAxis()));
    }
}
