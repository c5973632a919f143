package handsim.planning;

import handsim.control.CatchStyle;
import handsim.control.Observation;
import handsim.control.ThrowDecision;
import handsim.sim.SimulationDiverged;
import handsim.task.CatchThrowEpisode;
import handsim.task.LoopRecord;
import handsim.task.ThrowTask;
import java.util.SplittableRandom;

/**
 * A twin of a live episode: an episode in a world of its own ({@link CatchThrowEpisode#twinOn})
 * into which the live episode's checkpoints are restored, and where a throw, a catch or the
 * throw-in's catch is played out up to the next throw's decision. The twin steps on bit for bit as
 * the live world would, so what a throw makes here it makes live. The {@link ThrowPlanner} and
 * the {@link ThrowTeacher} try their throws here.
 */
final class TwinEpisode {

    /**
     * What one play made: the loop of the throw (or catch) played, the decision it leads to (null:
     * the episode ended first) and, when asked for, the checkpoint where THROW ended (else null).
     * {@link #FAILED}: the simulation diverged or the loop was never recorded.
     */
    record Outcome(LoopRecord loop, Observation next, CatchThrowEpisode.Checkpoint throwEnd) {

        static final Outcome FAILED = new Outcome(null, null, null);

        boolean failed() {
            return loop == null;
        }

        /** The task counts the loop a success and the episode goes on to a next decision. */
        boolean success(ThrowTask task) {
            return loop != null && next != null && task.success(loop);
        }
    }

    private final CatchThrowEpisode twin;

    TwinEpisode(CatchThrowEpisode twin) {
        this.twin = twin;
    }

    /** The twin's episode, standing where the last play left it. */
    CatchThrowEpisode episode() {
        return twin;
    }

    /**
     * {@code decision} played from {@code from} (a decision) to the next decision or the end of the
     * episode; with {@code keepThrowEnd}, the twin's checkpoint where THROW ended is kept too.
     */
    Outcome play(CatchThrowEpisode.Checkpoint from, ThrowDecision decision, boolean keepThrowEnd) {
        twin.restore(from);
        try {
            twin.decide(decision);
            CatchThrowEpisode.Checkpoint end = keepThrowEnd && twin.advanceToThrowEnd() ? twin.checkpoint() : null;
            Observation next = twin.status() == CatchThrowEpisode.Status.RUNNING ? twin.advanceToDecision() : null;
            return made(from.loopCount(), next, end);
        } catch (SimulationDiverged e) {
            return Outcome.FAILED;
        }
    }

    /** The catch of the throw that ended THROW at {@code end} (loop {@code loopIndex}) played again, meeting the object as {@code style} says. */
    Outcome playCatch(CatchThrowEpisode.Checkpoint end, int loopIndex, CatchStyle style) {
        twin.restore(end);
        twin.meetComingCatchAs(style);
        return advance(loopIndex);
    }

    /** The throw-in of {@code start} (an episode started and not yet ticked) caught as {@code style} says, up to the first decision. */
    Outcome playThrowIn(CatchThrowEpisode.Checkpoint start, CatchStyle style) {
        twin.restore(start);
        twin.catchThrowInAs(style);
        return advance(0);
    }

    private Outcome advance(int loopIndex) {
        try {
            return made(loopIndex, twin.advanceToDecision(), null);
        } catch (SimulationDiverged e) {
            return Outcome.FAILED;
        }
    }

    private Outcome made(int loopIndex, Observation next, CatchThrowEpisode.Checkpoint throwEnd) {
        return twin.loops().size() > loopIndex ? new Outcome(twin.loops().get(loopIndex), next, throwEnd) : Outcome.FAILED;
    }

    /** {@code centre} plus a Gaussian of standard deviation {@code spread} per entry (action units, not clipped). */
    static double[] vary(double[] centre, double spread, SplittableRandom rng) {
        double[] a = centre.clone();
        for (int i = 0; i < a.length; i++) {
            a[i] += spread * gaussian(rng);
        }
        return a;
    }

    private static double gaussian(SplittableRandom rng) {
        return Math.sqrt(-2 * Math.log(1 - rng.nextDouble())) * Math.cos(2 * Math.PI * rng.nextDouble());
    }
}
