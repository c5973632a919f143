package handsim.train;

import handsim.control.Observation;
import handsim.control.ThrowPolicy;
import handsim.learn.Demonstration;
import handsim.learn.TeachableEnv;
import handsim.planning.ThrowTeacher;
import handsim.task.CatchThrowEpisode;
import java.util.function.Predicate;

/**
 * A {@link ThrowEnv} whose decisions a {@link ThrowTeacher} labels: the teacher plays throws in
 * a twin world from the decision the environment waits at and answers with the nearest that
 * works (DAgger's expert). With a {@link Gate} the environment waits only at the decisions the
 * gate lets through and throws the others itself with the gate's lead-in policy.
 */
public final class TeachableThrowEnv implements TeachableEnv {

    /**
     * Which decisions are the learner's: the throws after the first whose decision {@code
     * learnerThrows} accepts; the others are thrown by {@code leadIn} (given the throw's index,
     * {@link ThrowPolicy#decide(Observation, int)}), and an episode is cut off (truncated) after
     * throw number {@code maxLoops}, as evaluate's episodes are after their loop cap.
     */
    public record Gate(Predicate<Observation> learnerThrows, ThrowPolicy leadIn, int maxLoops) {
    }

    private final ThrowEnv env;
    private final ThrowTeacher teacher;
    private final Gate gate;

    public TeachableThrowEnv(ThrowEnv env, ThrowTeacher teacher) {
        this(env, teacher, null);
    }

    /** @param gate the decisions the learner makes, or null for all */
    public TeachableThrowEnv(ThrowEnv env, ThrowTeacher teacher, Gate gate) {
        this.env = env;
        this.teacher = teacher;
        this.gate = gate;
    }

    @Override
    public int observationSize() {
        return env.observationSize();
    }

    @Override
    public int actionSize() {
        return env.actionSize();
    }

    /** The first decision of the episode of {@code seed} that is the learner's, or null if the episode ends before one. */
    @Override
    public double[] reset(long seed) {
        double[] obs = env.reset(seed);
        Step led = leadInToLearner(new Step(obs, 0, false, false));
        return led.done() ? null : led.observation();
    }

    @Override
    public Step step(double[] action) {
        Step s = env.step(action);
        Step led = leadInToLearner(s);
        return led == s ? s : new Step(led.observation(), s.reward(), led.terminal(), led.truncated()); // the learner's throw's reward
    }

    /** From {@code s}, the lead-in's throws up to the learner's next decision or the episode's end. */
    private Step leadInToLearner(Step s) {
        while (gate != null && !s.done()) {
            CatchThrowEpisode episode = env.episode();
            int throwIndex = episode.loops().size();
            if (throwIndex > gate.maxLoops()) {
                return new Step(s.observation(), s.reward(), false, true); // cut off, not ended
            }
            if (throwIndex > 1 && gate.learnerThrows().test(episode.decision())) {
                return s;
            }
            s = env.throwWith(gate.leadIn().decide(episode.decision(), throwIndex));
        }
        return s;
    }

    @Override
    public Demonstration label(double[] proposal, long seed) {
        ThrowTeacher.Label l = teacher.label(env.episode(), proposal, seed);
        return new Demonstration(l.action(), l.proposalSucceeded(), l.tries(), l.robustness(),
                l.trials().stream().map(t -> new Demonstration.Trial(t.action(), t.success(), t.reward(), outcome(t.loop()))).toList());
    }

    /** What each trial's outcome records ({@link #outcome}): the loop's flight, in radians and rad/s. */
    public static final java.util.List<String> OUTCOMES = java.util.List.of("flight_rotation_rad", "release_spin_rad_s",
            "arrival_tilt_rad", "catch_tilt_rad", "caught");

    /** A trial's loop as numbers ({@link #OUTCOMES}; NaN throughout when the simulation diverged). */
    static double[] outcome(handsim.task.LoopRecord loop) {
        if (loop == null) {
            return new double[] {Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN};
        }
        return new double[] {loop.flightRotation(), loop.releaseSpin(), loop.arrivalTilt(), loop.catchTilt(), loop.caught() ? 1 : 0};
    }
}
