package handsim.cards.study;

import handsim.report.Stop;
import java.util.concurrent.CompletionService;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorCompletionService;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;

/** A study's trials on threads of this JVM, each calling the objective directly. */
final class ThreadTrials implements TrialExecutor {

    private final Objective objective;
    private final StudyConfig config;
    private final int workers;
    private final ExecutorService pool;
    private final CompletionService<TrialRecord> done;

    ThreadTrials(Objective objective, StudyConfig config, int workers) {
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
    public String describe() {
        return workers + (workers == 1 ? " worker" : " workers");
    }

    @Override
    public void start(int number, double[] params) {
        done.submit(() -> Study.trial(objective, config, number, params));
    }

    @Override
    public TrialRecord next() throws InterruptedException {
        Future<TrialRecord> next;
        while ((next = done.poll(Study.STOP_POLL_MILLIS, TimeUnit.MILLISECONDS)) == null) {
            if (Stop.requested()) {
                return null;
            }
        }
        try {
            return next.get();
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
