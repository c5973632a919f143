package handsim.cards.study;

/**
 * Where a study's trials are evaluated. The study decides which trial runs when and with what
 * parameters (trial k is a function of the seed, k and trials 0 … k − P); an executor only
 * evaluates them, each by {@link #evaluate}, a pure function of the objective, the config, the
 * trial's number and its parameters, and hands back the records in any order. {@link
 * LocalTrials}, a thread pool in this JVM, is the default; another executor (say a cluster's)
 * gives byte-identical studies as long as its objective is the same function.
 */
public interface TrialExecutor extends AutoCloseable {

    /** How many trials it evaluates at once. */
    int slots();

    /** Starts evaluating trial {@code number} with {@code params} (search-space order, own units). */
    void submit(int number, double[] params);

    /**
     * The next finished trial, waiting for one; an objective's exception is a failed record, a
     * failure of the executor itself is thrown.
     */
    TrialRecord take() throws InterruptedException;

    /** Abandons running trials and releases the workers. */
    @Override
    void close();

    /**
     * Trial {@code number} of {@code objective}: complete with its values and figures, or failed
     * with the error when the objective throws or returns a value that is not finite; the wall
     * time of the evaluation is kept.
     */
    static TrialRecord evaluate(Objective objective, StudyConfig config, int number, double[] params) {
        long t0 = System.nanoTime();
        Evaluation e;
        try {
            e = objective.evaluate(TrialParams.of(number, config, params));
        } catch (Exception ex) {
            return TrialRecord.failed(number, params, ex.toString(), (System.nanoTime() - t0) * 1e-9);
        }
        double seconds = (System.nanoTime() - t0) * 1e-9;
        double[] values = e.values();
        if (values.length != config.objectives().size()) {
            throw new IllegalStateException("the objective returned " + values.length + " values for the study's " + config.objectives().size()
                    + " objectives " + config.objectives());
        }
        for (int i = 0; i < values.length; i++) {
            if (!Double.isFinite(values[i])) {
                return TrialRecord.failed(number, params, config.objectives().get(i) + " is " + values[i], seconds);
            }
        }
        return TrialRecord.complete(number, params, e, seconds);
    }
}
