package handsim.learn;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Future;

/** Independent tasks on an executor, results in input order (whatever finished first). */
final class Parallel {

    private Parallel() {
    }

    /** Runs the tasks and waits for all; {@code what} names one task in error messages. */
    static <T> List<T> inOrder(ExecutorService executor, List<Callable<T>> tasks, String what) {
        List<Future<T>> futures = new ArrayList<>();
        for (Callable<T> task : tasks) {
            futures.add(executor.submit(task));
        }
        List<T> out = new ArrayList<>();
        try {
            for (Future<T> f : futures) {
                out.add(f.get());
            }
        } catch (InterruptedException e) {
            futures.forEach(f -> f.cancel(true));
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for a " + what, e);
        } catch (ExecutionException e) {
            futures.forEach(f -> f.cancel(true));
            throw new IllegalStateException("a " + what + " failed: " + e.getCause(), e.getCause());
        }
        return out;
    }
}
