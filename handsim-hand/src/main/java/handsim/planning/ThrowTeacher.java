package handsim.planning;

import handsim.config.Json;
import handsim.control.ThrowDecision;
import handsim.control.ThrowSpace;
import handsim.sim.Simulator;
import handsim.task.CatchThrowEpisode;
import handsim.task.LoopRecord;
import handsim.task.ThrowTask;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.SplittableRandom;

/**
 * The expert of imitation learning by dataset aggregation (DAgger, Ross, Gordon and Bagnell
 * 2011): at a decision a learner reached, it labels the learner's proposed throw with the nearest
 * throw it finds to succeed. It plays throws in a twin world ({@link TwinEpisode}), as the {@link
 * ThrowPlanner} does (an exact copy of the episode, played through the flight, the catch and
 * MIDDLE up to the next throw); it is a teacher for training and is never needed when the learned
 * policy runs.
 *
 * <p>The proposal is tried first: when it succeeds it is its own label. Otherwise the rounds go
 * in order, each drawing {@code candidates} throws around the proposal (a Gaussian of its {@code
 * spread} in action units, [-1, 1] per entry, clipped to the box) and trying them nearest first:
 * the first that succeeds, the nearest success of the round's sample, is the label. With a
 * robustness check, {@code robustnessTries} throws around the label (a Gaussian of {@code
 * robustnessSpread}) are played too, and the share of them that succeed says how robust a target
 * the label is: a success whose neighbours also succeed is a better thing to imitate than a lucky
 * one. With {@code centre}, the label then moves to the mean of itself and its neighbours that
 * succeeded, when that mean, played too, succeeds: the nearest success lies on the edge of the
 * throws that work, and a learner fitted to edges sits on them and fails about half the time.
 */
public final class ThrowTeacher {

    /** Up to {@code candidates} throws drawn around the proposal with standard deviation {@code spread} (action units). */
    public record Round(int candidates, double spread) {

        static Round parse(Json j) {
            j.allow("comment");
            Round r = new Round(j.integer("candidates", 1, 10000), j.number("spread", 0, 2));
            j.requireNoUnknownFields();
            return r;
        }
    }

    /**
     * The {@code teacher} section of a DAgger config ({@code configs/train/flip-dagger.json}).
     *
     * @param rounds the search after a failed proposal, in order; a round begins only when the earlier ones found no success
     * @param robustnessTries throws played around a found label to measure its robustness (0: none)
     * @param robustnessSpread their standard deviation (action units)
     * @param centre move the label to the mean of its successful neighbours when that succeeds too
     */
    public record Config(List<Round> rounds, int robustnessTries, double robustnessSpread, boolean centre) {

        public Config {
            rounds = List.copyOf(rounds);
        }

        public static Config parse(Json j) {
            j.allow("comment");
            List<Json> list = j.array("rounds");
            if (list.isEmpty()) {
                throw j.fieldError("rounds", "needs at least one round, got []");
            }
            Config c = new Config(list.stream().map(Round::parse).toList(), j.integer("robustnessTries", 0, 1000),
                    j.number("robustnessSpread", 0, 2), j.bool("centre", false));
            if (c.centre && c.robustnessTries == 0) {
                throw j.fieldError("centre", "moves the label among the robustness check's throws: set robustnessTries > 0");
            }
            j.requireNoUnknownFields();
            return c;
        }

        /** The most throws one label costs. */
        public int maxTries() {
            return 1 + rounds.stream().mapToInt(Round::candidates).sum() + robustnessTries + (centre ? 1 : 0);
        }
    }

    /**
     * One throw played in the twin: the action (units of the box, [-1, 1] per entry), whether the
     * task counted it a success, its reward, and the loop it made (null when the simulation diverged).
     */
    public record Trial(double[] action, boolean success, double reward, LoopRecord loop) {
    }

    /**
     * The teacher's answer at one decision.
     *
     * @param action the label (action units), or null when no try succeeded
     * @param proposalSucceeded the learner's own throw succeeded (and is then the label)
     * @param robustness the share of the robustness check's throws around the label that succeeded (1 without a
     *     check, 0 without a label)
     * @param trials every throw played, in order (the proposal first; the robustness check's last)
     */
    public record Label(double[] action, boolean proposalSucceeded, double robustness, List<Trial> trials) {

        public Label {
            trials = List.copyOf(trials);
        }

        /** Throws played for this label. */
        public int tries() {
            return trials.size();
        }
    }

    private final Config config;
    private final ThrowTask task;
    private final ThrowSpace space;
    private final Simulator twinWorld;
    /** The live episode the twin copies, and the twin. */
    private CatchThrowEpisode twinOf;
    private TwinEpisode twin;

    /**
     * @param twin a simulator of the live episodes' model and config with an engine of its own (the caller closes it)
     * @param task the task whose success counts; its goal must not change from throw to throw
     */
    public ThrowTeacher(Config config, ThrowTask task, ThrowSpace space, Simulator twin) {
        task.requireFixedGoal("throw teacher");
        this.config = config;
        this.task = task;
        this.space = space;
        this.twinWorld = twin;
    }

    /**
     * The label of the decision {@code live} waits at ({@link CatchThrowEpisode#advanceToDecision})
     * for the learner's {@code proposal} (action units); {@code seed} seeds the variations. The
     * live episode is left as it was.
     */
    public Label label(CatchThrowEpisode live, double[] proposal, long seed) {
        if (live.decision() == null) {
            throw new IllegalStateException("the teacher labels a decision: the episode must be at a throw's decision");
        }
        if (twinOf != live) {
            twin = new TwinEpisode(live.twinOn(twinWorld));
            twinOf = live;
        }
        CatchThrowEpisode.Checkpoint now = live.checkpoint();
        SplittableRandom rng = new SplittableRandom(seed);
        List<Trial> trials = new ArrayList<>();
        double[] start = clip(proposal);
        Trial first = play(now, start);
        trials.add(first);
        double[] label = first.success() ? start : null;
        for (int r = 0; label == null && r < config.rounds().size(); r++) {
            Round round = config.rounds().get(r);
            List<double[]> sample = new ArrayList<>();
            for (int c = 0; c < round.candidates(); c++) {
                sample.add(around(start, round.spread(), rng));
            }
            sample.sort(Comparator.comparingDouble(a -> distanceSquared(a, start)));
            for (double[] candidate : sample) {
                Trial t = play(now, candidate);
                trials.add(t);
                if (t.success()) {
                    label = candidate;
                    break;
                }
            }
        }
        double robustness = label == null ? 0 : 1;
        if (label != null && config.robustnessTries() > 0) {
            double[] sum = label.clone();
            int held = 0;
            for (int k = 0; k < config.robustnessTries(); k++) {
                Trial t = play(now, around(label, config.robustnessSpread(), rng));
                trials.add(t);
                if (t.success()) {
                    held++;
                    for (int i = 0; i < sum.length; i++) {
                        sum[i] += t.action()[i];
                    }
                }
            }
            robustness = (double) held / config.robustnessTries();
            if (config.centre() && held > 0) {
                double[] mean = new double[sum.length];
                for (int i = 0; i < sum.length; i++) {
                    mean[i] = sum[i] / (held + 1);
                }
                Trial t = play(now, mean);
                trials.add(t);
                if (t.success()) {
                    label = mean;
                }
            }
        }
        return new Label(label, first.success(), robustness, trials);
    }

    /** {@code action} played from {@code from} in the twin, up to the next decision or the episode's end. */
    private Trial play(CatchThrowEpisode.Checkpoint from, double[] action) {
        TwinEpisode.Outcome o = twin.play(from, ThrowDecision.of(space.fromAction(action)), false);
        return o.failed() ? new Trial(action, false, Double.NEGATIVE_INFINITY, null)
                : new Trial(action, o.success(task), task.reward(o.loop()), o.loop());
    }

    /** A Gaussian of {@code spread} around {@code centre}, clipped to the box. */
    private static double[] around(double[] centre, double spread, SplittableRandom rng) {
        return clip(TwinEpisode.vary(centre, spread, rng));
    }

    private static double[] clip(double[] a) {
        double[] c = new double[a.length];
        for (int i = 0; i < a.length; i++) {
            c[i] = Math.max(-1, Math.min(1, a[i]));
        }
        return c;
    }

    private static double distanceSquared(double[] a, double[] b) {
        double d = 0;
        for (int i = 0; i < a.length; i++) {
            d += (a[i] - b[i]) * (a[i] - b[i]);
        }
        return d;
    }
}
