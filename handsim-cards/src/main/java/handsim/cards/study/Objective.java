package handsim.cards.study;

/**
 * What a study optimises: a trial's parameters in, its objective values out (one per objective
 * of the {@link StudyConfig}, in that order). Card Snapping's trial implements it by simulating
 * the sleight with the suggested bone trajectory.
 *
 * <p>Called from the study's worker threads, several at once: an implementation keeps no
 * mutable state shared between calls. A thrown exception, or a value that is not finite, marks
 * the trial failed: it is recorded with the error and left out of what the sampler learns from
 * (as Optuna leaves out failed trials); a {@link TrialFailed} says why in its message (a trial
 * past its budget). A worker thread is interrupted when the study stops.
 */
@FunctionalInterface
public interface Objective {

    Evaluation evaluate(TrialParams params) throws Exception;

    /** A trial that failed for a reason its message gives in one line (a budget it went past, say). */
    final class TrialFailed extends RuntimeException {
        private static final long serialVersionUID = 1L;

        public TrialFailed(String reason, Throwable cause) {
            super(reason, cause);
        }
    }
}
