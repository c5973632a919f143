package handsim.cards.study;

/**
 * What runs a study's trials: this JVM's threads ({@link Study#run(Objective, int, int,
 * java.io.PrintStream)}) or a cluster's executors ({@link RemoteTrials}). The study suggests each
 * trial's parameters and writes every file; an executor only runs trials and hands back their
 * records, in whatever order they finish.
 */
public interface TrialExecutor extends AutoCloseable {

    /** How many trials it runs at once; the study also runs at most its parallelTrials. */
    int slots();

    /** What runs the trials, for the study's first progress line ("2 workers"). */
    String describe();

    /** Starts trial {@code number} at {@code params} (the search space's order). */
    void start(int number, double[] params);

    /**
     * Waits for a started trial to finish and returns its record: the next to finish, whichever it
     * is; or null once a stop is requested ({@code handsim.report.Stop}) while it waits.
     */
    TrialRecord next() throws InterruptedException;

    /** Abandons the trials still running (a resumed study runs them again). */
    @Override
    void close();
}
