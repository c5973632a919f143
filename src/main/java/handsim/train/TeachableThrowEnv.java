package handsim.train;

import handsim.learn.Demonstration;
import handsim.learn.TeachableEnv;
import handsim.evaluation.ThrowTeacher;

/**
 * A {@link ThrowEnv} whose decisions a {@link ThrowTeacher} labels: the teacher plays throws in
 * a twin world from the decision the environment waits at and answers with the nearest that
 * works (DAgger's expert).
 */
public final class TeachableThrowEnv implements TeachableEnv {

    private final ThrowEnv env;
    private final ThrowTeacher teacher;

    public TeachableThrowEnv(ThrowEnv env, ThrowTeacher teacher) {
        this.env = env;
        this.teacher = teacher;
    }

    @Override
    public int observationSize() {
        return env.observationSize();
    }

    @Override
    public int actionSize() {
        return env.actionSize();
    }

    @Override
    public double[] reset(long seed) {
        return env.reset(seed);
    }

    @Override
    public Step step(double[] action) {
        return env.step(action);
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
