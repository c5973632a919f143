package handsim.app;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * Where the time of the step loop goes, by sampling: a daemon thread takes the stack of every
 * registered thread every {@code periodMillis} and puts the sample in the first category whose
 * marker is on the stack (anywhere, so the leaf's safepoint bias does not matter). The shares
 * are fractions of the samples; sampling at 200 Hz costs well under 1 % of the loop.
 */
final class StackSampler implements AutoCloseable {

    /** Categories in matching order: a marker is a prefix of "class.method" of some frame. */
    private static final Map<String, List<String>> CATEGORIES = new LinkedHashMap<>();

    static {
        CATEGORIES.put("solver", List.of("org.ode4j.ode.internal.DxWorld.quickStep", "org.ode4j.ode.internal.DxWorld.dWorldQuickStep"));
        CATEGORIES.put("collision", List.of("handsim.sim.ode.OdeSimulator.collide"));
        CATEGORIES.put("ik", List.of("handsim.control.DlsIk."));
        CATEGORIES.put("controller", List.of("handsim.control."));
        CATEGORIES.put("engine_glue", List.of("handsim.sim.ode.OdeSimulator."));
        CATEGORIES.put("episode", List.of("handsim.task."));
    }

    private final List<Thread> threads = new CopyOnWriteArrayList<>();
    private final Map<String, Integer> counts = new LinkedHashMap<>();
    private final Thread sampler;
    private volatile boolean running = true;
    private volatile boolean recording;
    private int samples;

    StackSampler(long periodMillis) {
        for (String c : CATEGORIES.keySet()) {
            counts.put(c, 0);
        }
        counts.put("other", 0);
        sampler = new Thread(() -> {
            while (running) {
                try {
                    Thread.sleep(periodMillis);
                } catch (InterruptedException e) {
                    return;
                }
                if (recording) {
                    for (Thread t : threads) {
                        record(t.getStackTrace());
                    }
                }
            }
        }, "stack-sampler");
        sampler.setDaemon(true);
        sampler.start();
    }

    /** Samples the calling thread from now on. */
    void register() {
        threads.add(Thread.currentThread());
    }

    void unregister() {
        threads.remove(Thread.currentThread());
    }

    /** Starts counting samples (after warm-up). */
    void start() {
        recording = true;
    }

    private synchronized void record(StackTraceElement[] stack) {
        if (stack.length == 0) {
            return;
        }
        samples++;
        for (var c : CATEGORIES.entrySet()) {
            for (StackTraceElement e : stack) {
                String frame = e.getClassName() + "." + e.getMethodName();
                for (String marker : c.getValue()) {
                    if (frame.startsWith(marker)) {
                        counts.merge(c.getKey(), 1, Integer::sum);
                        return;
                    }
                }
            }
        }
        counts.merge("other", 1, Integer::sum);
    }

    synchronized int samples() {
        return samples;
    }

    /** Fraction of the samples in each category, in matching order, then "other". */
    synchronized Map<String, Double> shares() {
        Map<String, Double> out = new LinkedHashMap<>();
        for (var e : counts.entrySet()) {
            out.put(e.getKey(), samples == 0 ? 0 : e.getValue() / (double) samples);
        }
        return out;
    }

    @Override
    public void close() {
        running = false;
        sampler.interrupt();
    }
}
