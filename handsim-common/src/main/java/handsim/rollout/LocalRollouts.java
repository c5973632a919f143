package handsim.rollout;

import handsim.report.Stop;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;

/**
 * Rollouts on worker threads of this JVM. Each worker owns one resource for its lifetime (made
 * by the factory on first use and reused across runs, closed with the rollouts when it is
 * {@link AutoCloseable}); the rollouts of a run are handed out one index at a time to whichever
 * worker is free. Since a rollout depends on its index alone, which worker runs it does not
 * change its result. The resources must not share mutable state: for ode4j simulators use {@code
 * IsolatedEngine}, which gives each its own copy of the engine's statics.
 */
public final class LocalRollouts<W> implements Rollouts<W> {

    /** How often the caller, waiting for rollouts, looks for a stop request (ms): well below a person's patience. */
    private static final long STOP_POLL_MILLIS = 100;

    private final int workers;
    private final Supplier<W> resources;
    private final Object[] owned;
    private final ExecutorService pool;

    /** {@code workers} threads (at least 1), each worker's resource from {@code resources}. */
    public LocalRollouts(int workers, Supplier<W> resources) {
        if (workers < 1) {
            throw new IllegalArgumentException("workers must be at least 1, got " + workers);
        }
        this.workers = workers;
        this.resources = resources;
        this.owned = new Object[workers];
        AtomicInteger made = new AtomicInteger();
        this.pool = Executors.newFixedThreadPool(workers, r -> {
            Thread t = new Thread(r, "rollout-" + made.getAndIncrement());
            t.setDaemon(true);
            return t;
        });
    }

    /** The number of processors this JVM may use: the default worker count. */
    public static int localCores() {
        return Runtime.getRuntime().availableProcessors();
    }

    @Override
    public int workers() {
        return workers;
    }

    /** A finished rollout on the queue to the caller: a result, or the failure that stops the run. */
    private record Done(int index, Object result, Throwable failure) {
    }

    @Override
    public <R> List<R> run(int count, RolloutTask<W, R> task, Listener<? super R> listener) {
        if (count < 0) {
            throw new IllegalArgumentException("count must be >= 0, got " + count);
        }
        AtomicInteger next = new AtomicInteger();
        AtomicBoolean stop = new AtomicBoolean();
        LinkedBlockingQueue<Done> done = new LinkedBlockingQueue<>();
        List<Future<?>> running = new ArrayList<>();
        for (int w = 0; w < Math.min(workers, count); w++) {
            int worker = w;
            running.add(pool.submit(() -> {
                try {
                    RolloutTask.Rollout<R> rollout = task.prepare(resource(worker));
                    for (int i = next.getAndIncrement(); i < count && !stop.get() && !Stop.requested(); i = next.getAndIncrement()) {
                        done.add(new Done(i, rollout.run(i), null));
                    }
                } catch (Throwable t) {
                    done.add(new Done(-1, null, t));
                }
            }));
        }
        Object[] results = new Object[count];
        boolean[] finished = new boolean[count];
        int emitted = 0;
        boolean abandoned = false;
        try (Stop.Watch watch = Stop.watch()) {
            for (int received = 0; received < count; received++) {
                Done d = done.poll(STOP_POLL_MILLIS, TimeUnit.MILLISECONDS);
                if (d == null) {
                    if (Stop.requested()) {
                        abandoned = true; // the rollouts under way are left to the workers, not waited for
                        Stop.check(emitted + " of " + count + " rollouts finished, the ones under way abandoned");
                    }
                    received--;
                    continue;
                }
                if (d.failure() != null) {
                    stop.set(true);
                    throw rethrow(d.failure());
                }
                results[d.index()] = d.result();
                finished[d.index()] = true;
                while (emitted < count && finished[emitted]) {
                    @SuppressWarnings("unchecked")
                    R r = (R) results[emitted];
                    listener.onResult(emitted, r);
                    emitted++;
                }
            }
        } catch (InterruptedException e) {
            stop.set(true);
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for rollouts", e);
        } finally {
            stop.set(true);
            if (!abandoned) {
                awaitAll(running);
            }
        }
        @SuppressWarnings("unchecked")
        List<R> out = (List<R>) Arrays.asList(results);
        return Collections.unmodifiableList(out);
    }

    /** Worker {@code w}'s resource; only the thread running worker w's task touches it. */
    @SuppressWarnings("unchecked")
    private W resource(int w) {
        Object r;
        synchronized (owned) {
            r = owned[w];
        }
        if (r == null) {
            r = resources.get();
            synchronized (owned) {
                owned[w] = r;
            }
        }
        return (W) r;
    }

    private static void awaitAll(List<Future<?>> running) {
        for (Future<?> f : running) {
            try {
                f.get();
            } catch (Exception e) {
                // failures were reported through the queue; here we only wait for the workers to stop
            }
        }
    }

    private static RuntimeException rethrow(Throwable t) {
        if (t instanceof RuntimeException r) {
            return r;
        }
        if (t instanceof Error e) {
            throw e;
        }
        return new IllegalStateException("rollout failed", t);
    }

    @Override
    public void close() {
        pool.shutdownNow();
        synchronized (owned) {
            for (int w = 0; w < owned.length; w++) {
                if (owned[w] instanceof AutoCloseable c) {
                    closeQuietly(c);
                }
                owned[w] = null;
            }
        }
    }

    private static void closeQuietly(AutoCloseable c) {
        try {
            c.close();
        } catch (RuntimeException e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalStateException("a rollout worker's resource failed to close", e);
        }
    }
}
