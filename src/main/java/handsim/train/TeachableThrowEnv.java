package handsim.train;

import handsim.learn.Demonstration;
import handsim.learn.TeachableEnv;
import handsim.task.ThrowTeacher;

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
                l.trials().stream().map(t -> new Demonstration.Trial(t.action(), t.success(), t.reward())).toList());
    }
}
