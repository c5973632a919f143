package handsim.cards.study;

import java.util.concurrent.CompletionService;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorCompletionService;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

/** Trials on a pool of worker threads in this JVM: the default {@link TrialExecutor}. */
public final class LocalTrials implements TrialExecutor {

    private final Objective objective;
    private final StudyConfig config;
    private final int workers;
    private final ExecutorService pool;
    private final CompletionService<TrialRecord> done;

    /** {@code workers} threads (≥ 1) evaluating {@code objective}, several at once. */
    public LocalTrials(Objective objective, StudyConfig config, int workers) {
        if (workers < 1) {
            throw new IllegalArgumentException("workers: must be >= 1, got " + workers);
        }
        this.objective = objective;
        this.config = config;
        this.workers = workers;
        this.pool = Executors.newFixedThreadPool(workers, r -> {
            Thread t = new Thread(r, "study-worker");
            t.setDaemon(true);
            return t;
        });
        this.done = new ExecutorCompletionService<>(pool);
    }

    @Override
    public int slots() {
        return workers;
    }

    @Override
    public void submit(int number, double[] params) {
        double[] p = params.clone();
        done.submit(() -> TrialExecutor.evaluate(objective, config, number, p));
    }

    @Override
    public TrialRecord take() throws InterruptedException {
        try {
            return done.take().get();
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof RuntimeException r) {
                throw r;
            }
            if (cause instanceof Error err) {
                throw err;
            }
            throw new IllegalStateException(cause);
        }
    }

    @Override
    public void close() {
        pool.shutdownNow();
    }
}
