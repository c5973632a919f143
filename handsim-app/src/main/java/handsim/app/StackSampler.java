package handsim.app;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import jdk.jfr.Recording;
import jdk.jfr.consumer.RecordedEvent;
import jdk.jfr.consumer.RecordedFrame;
import jdk.jfr.consumer.RecordingFile;

/**
 * Which code the step loop's samples are in, from the JVM's own execution sampler (JFR's
 * {@code jdk.ExecutionSample}): it stops threads anywhere in Java code, not only at safepoints
 * (sampling with {@code Thread.getStackTrace} moved samples out of the solver's long compiled
 * loops). It does not see threads in native code, such as {@code StrictMath.atan2}, so the
 * bench times the simulator's phases directly and uses this only to split the controller's
 * share (the DLS IK). Each sample of a registered thread inside the measured window goes to the
 * first category whose marker is on its stack. JFR keeps the 64 frames nearest the leaf: a sample whose leaf is in ode4j and
 * whose visible frames name no handsim caller is deep inside quickStep, so it is the solver's.
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

    private final Recording recording = new Recording();
    private final Set<Long> threads = ConcurrentHashMap.newKeySet();
    private volatile Instant from;
    private volatile Instant to;
    private final Map<String, Integer> counts = new LinkedHashMap<>();
    private int samples;

    StackSampler(long periodMillis) {
        recording.enable("jdk.ExecutionSample").withPeriod(Duration.ofMillis(periodMillis));
        recording.start();
    }

    /** Samples the calling thread. */
    void register() {
        threads.add(Thread.currentThread().getId());
    }

    /** Opens the measured window (after warm-up). */
    void start() {
        from = Instant.now();
    }

    /** Closes the measured window. */
    void closeWindow() {
        to = Instant.now();
    }

    /** Stops sampling and counts the samples of the window. */
    void stop() {
        if (to == null) {
            closeWindow();
        }
        recording.stop();
        for (String c : CATEGORIES.keySet()) {
            counts.put(c, 0);
        }
        counts.put("other", 0);
        if (from == null) {
            return;
        }
        try {
            Path file = Files.createTempFile("handsim-bench", ".jfr");
            try {
                recording.dump(file);
                for (RecordedEvent e : RecordingFile.readAllEvents(file)) {
                    if (e.getEventType().getName().equals("jdk.ExecutionSample") && e.getStackTrace() != null
                            && threads.contains(e.getThread("sampledThread").getJavaThreadId())
                            && !e.getStartTime().isBefore(from) && !e.getStartTime().isAfter(to)) {
                        record(e.getStackTrace().getFrames());
                    }
                }
            } finally {
                Files.deleteIfExists(file);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the bench's execution samples", e);
        }
    }

    private void record(List<RecordedFrame> stack) {
        if (stack.isEmpty()) {
            return;
        }
        samples++;
        for (var c : CATEGORIES.entrySet()) {
            for (RecordedFrame f : stack) {
                String frame = f.getMethod().getType().getName() + "." + f.getMethod().getName();
                for (String marker : c.getValue()) {
                    if (frame.startsWith(marker)) {
                        counts.merge(c.getKey(), 1, Integer::sum);
                        return;
                    }
                }
            }
        }
        // a truncated stack deep in ode4j with no handsim frame left: the solver
        boolean handsim = stack.stream().anyMatch(f -> f.getMethod().getType().getName().startsWith("handsim."));
        String leaf = stack.get(0).getMethod().getType().getName();
        counts.merge(!handsim && leaf.startsWith("org.ode4j.") ? "solver" : "other", 1, Integer::sum);
    }

    int samples() {
        return samples;
    }

    /** Fraction of the samples in each category, in matching order, then "other". */
    Map<String, Double> shares() {
        Map<String, Double> out = new LinkedHashMap<>();
        for (var e : counts.entrySet()) {
            out.put(e.getKey(), samples == 0 ? 0 : e.getValue() / (double) samples);
        }
        return out;
    }

    @Override
    public void close() {
        recording.close();
    }
}
