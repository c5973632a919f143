package handsim.spark;

import handsim.report.Durations;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * A batch's progress on the driver: every few seconds the calls done of the total, those
 * running, attempts failed and an ETA; at the end the wall time, the attempts run again with the
 * executor time they lost, and the overhead of a call: its time from submission to result beyond
 * its own time on the executor (queueing included when more calls are submitted than cores).
 */
final class BatchProgress {

    private final PrintStream out;
    private final String what;
    private final int total;
    private final TaskWatch.Losses losses;
    private final long t0 = System.nanoTime();
    private final ScheduledExecutorService ticker = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "spark-progress");
        t.setDaemon(true);
        return t;
    });
    private int submitted;
    private int done;
    private int failed;
    private long roundTripNanos;
    private long callNanos;
    /** Each call's time from submission to result beyond its own time on the executor, ns. */
    private final List<Long> overheads = new ArrayList<>();

    BatchProgress(PrintStream out, String what, int total, double everySeconds, TaskWatch.Losses losses) {
        this.out = out;
        this.what = what;
        this.total = total;
        this.losses = losses;
        long period = Math.round(everySeconds * 1000);
        ticker.scheduleAtFixedRate(this::line, period, period, TimeUnit.MILLISECONDS);
    }

    String what() {
        return what;
    }

    synchronized void submitted() {
        submitted++;
    }

    synchronized void finished(long roundTrip, long call) {
        done++;
        roundTripNanos += roundTrip;
        callNanos += call;
        overheads.add(roundTrip - call);
    }

    synchronized void failed() {
        failed++;
    }

    private synchronized void line() {
        double elapsed = seconds();
        String eta = done == 0 || total <= 0 ? "" : ", ETA " + Durations.clock((total - done) * elapsed / done);
        out.printf(Locale.ROOT, "spark: %d%s %s done, %d running, %d failed, %d attempts run again; %s%s%n", done,
                total > 0 ? "/" + total : "", what, running(), failed, losses.attempts.get(), Durations.clock(elapsed), eta);
        out.flush();
    }

    /** Calls submitted and not yet back. */
    synchronized int running() {
        return submitted - done - failed;
    }

    synchronized void close(String where) {
        ticker.shutdownNow();
        if (submitted == 0) {
            return;
        }
        int tasks = losses.succeeded.get();
        double call = callNanos * 1e-9 / Math.max(1, done);
        double onExecutor = tasks == 0 ? 0 : losses.taskMillis.get() / 1000.0 / tasks - call;
        double roundTrip = roundTripNanos * 1e-9 / Math.max(1, done);
        double median = overheads.isEmpty() ? 0 : overheads.stream().sorted().toList().get(overheads.size() / 2) * 1e-9;
        String perCall = done == 0 ? "" : String.format(Locale.ROOT, "; a call: %.3f s in the call, overhead %.3f s (%.2f %%; median %.3f s): "
                + "%.3f s on its executor around the call, %.3f s from submission to launch and from end to result (queueing included "
                + "when more calls are in flight than cores)", call, roundTrip - call, 100 * (roundTrip - call) / Math.max(1e-9, call),
                median, onExecutor, roundTrip - call - onExecutor);
        out.printf(Locale.ROOT, "spark: %d %s done in %s on %s; %d failed; %d attempts lost with their executors and run again "
                + "(%.1f s of executor time lost)%s%n", done, what, Durations.clock(seconds()), where, failed, losses.attempts.get(),
                losses.millis.get() / 1000.0, perCall);
        out.flush();
    }

    private double seconds() {
        return (System.nanoTime() - t0) * 1e-9;
    }
}
