package handsim.spark;

import handsim.rollout.PortableCall;
import handsim.rollout.RemoteCalls;
import handsim.rollout.RemoteFailure;
import java.io.PrintStream;
import java.io.Serializable;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import org.apache.spark.api.java.JavaSparkContext;

/**
 * handsim's calls on a Spark application: each call is a job of one task (one partition holding
 * the call), submitted from a driver thread of its own so that results come back as each
 * finishes; Spark schedules the tasks on free executor cores and runs a task again when its
 * executor is lost. Calls of a batch share a job group (cancelled together).
 */
final class SparkCalls implements RemoteCalls {

    private final JavaSparkContext sc;
    private final String master;
    private final SparkSettings settings;
    private final PrintStream out;
    private final TaskWatch watch;
    private final ExecutorService submitters = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "spark-call");
        t.setDaemon(true);
        return t;
    });
    private final AtomicInteger batches = new AtomicInteger();

    SparkCalls(JavaSparkContext sc, String master, SparkSettings settings, PrintStream out) {
        this.sc = sc;
        this.master = master;
        this.settings = settings;
        this.out = out;
        this.watch = new TaskWatch(out);
        sc.sc().addSparkListener(watch);
    }

    /** Executors registered, the driver not counted (0 in local mode, where the driver runs the calls). */
    int executors() {
        return Math.max(0, sc.statusTracker().getExecutorInfos().length - 1);
    }

    @Override
    public int slots() {
        return sc.defaultParallelism();
    }

    @Override
    public String describe() {
        return master.startsWith("local") ? master + " (" + slots() + " threads of this JVM)"
                : master + " (" + executors() + " executors registered, " + slots() + " cores)";
    }

    @Override
    public Batch batch(String what, int total) {
        return new SparkBatch("handsim-" + batches.incrementAndGet(), what, total);
    }

    @Override
    public void close() {
        submitters.shutdownNow();
        sc.stop();
    }

    /** Calls of one batch: a job group, its progress lines and its summary. */
    private final class SparkBatch implements Batch {

        private final String group;
        private final BatchProgress progress;

        SparkBatch(String group, String what, int total) {
            this.group = group;
            this.progress = new BatchProgress(out, what, total, settings.progressSeconds(), watch.losses(group));
        }

        @Override
        @SuppressWarnings("unchecked")
        public <R extends Serializable> CompletableFuture<R> submit(PortableCall<R> call) {
            CompletableFuture<R> result = new CompletableFuture<>();
            String label = call.label();
            progress.submitted();
            long t0 = System.nanoTime();
            submitters.execute(() -> {
                try {
                    sc.setJobGroup(group, progress.what(), true);
                    sc.setJobDescription(label);
                    List<PortableCall<?>> one = List.of(call);
                    Timed t = sc.parallelize(one, 1).map(RunCall.INSTANCE).collect().get(0);
                    progress.finished(System.nanoTime() - t0, t.nanos());
                    if (t.failure() != null) {
                        out.printf(Locale.ROOT, "spark: %s failed on executor %s: %s%n", label, t.executor(), t.failure());
                        result.completeExceptionally(t.failure());
                    } else {
                        result.complete((R) t.value());
                    }
                } catch (Exception e) { // SparkException is checked, though Scala does not declare it
                    progress.failed();
                    String why = String.valueOf(e.getMessage()).lines().findFirst().orElse("");
                    result.completeExceptionally(new RemoteFailure(label + ": the cluster did not run it: " + why, e));
                }
            });
            return result;
        }

        @Override
        public void close() {
            if (progress.running() > 0) {
                sc.cancelJobGroup(group);
            }
            progress.close(executors() > 0 ? executors() + " executors" : master);
        }
    }

    /** The master a driver under spark-submit was given, else null. */
    static String submittedMaster() {
        return System.getProperty("spark.master");
    }
}
