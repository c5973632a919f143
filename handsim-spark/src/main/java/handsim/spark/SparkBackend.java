package handsim.spark;

import handsim.config.Home;
import handsim.config.Json;
import handsim.rollout.RemoteBackend;
import handsim.rollout.RemoteCalls;
import java.io.IOException;
import java.io.PrintStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaSparkContext;

/**
 * Apache Spark as handsim's cluster engine (found by {@link java.util.ServiceLoader}): a Spark
 * application per command, its executors given handsim's classes (at the driver's paths or as
 * jars, {@code configs/spark.json} code), one core per call, {@code OMP_NUM_THREADS=1}.
 */
public final class SparkBackend implements RemoteBackend {

    private static final Pattern STANDALONE = Pattern.compile("spark://([^:/\\s,]+):(\\d+)");
    private static final Pattern MASTER = Pattern.compile("spark://[^/\\s]+|local(\\[(\\d+|\\*)(,\\d+)?])?|yarn|k8s://\\S+");
    /** How long a standalone master's port is given to answer before the master is refused, ms. */
    private static final int PROBE_MILLIS = 3000;

    @Override
    public String name() {
        return "Apache Spark";
    }

    @Override
    public RemoteCalls connect(String master, String application, PrintStream progress) {
        if (!MASTER.matcher(master).matches()) {
            throw new IllegalArgumentException("--master must be spark://HOST:PORT, local[N], yarn or k8s://HOST:PORT, got \"" + master + "\"");
        }
        Matcher standalone = STANDALONE.matcher(master);
        if (standalone.matches()) {
            probe(master, standalone.group(1), Integer.parseInt(standalone.group(2)));
        }
        SparkSettings settings = SparkSettings.parse(Json.load(Home.resolve(SparkSettings.FILE)));
        SparkConf conf = new SparkConf().setMaster(master).setAppName(application)
                .setIfMissing("spark.executor.memory", settings.executorMemory())
                .setIfMissing("spark.executor.extraJavaOptions", settings.executorJavaOptions())
                .setIfMissing("spark.executorEnv.OMP_NUM_THREADS", "1")
                .setIfMissing("spark.task.maxFailures", Integer.toString(settings.taskMaxFailures()))
                .setIfMissing("spark.ui.enabled", "false");
        if (!master.startsWith("local")) {
            if (settings.shipJars()) {
                conf.setIfMissing("spark.jars", String.join(",", CodeJars.forExecutors()));
            } else {
                conf.setIfMissing("spark.executor.extraClassPath", CodeJars.classpath());
            }
        }
        JavaSparkContext sc = new JavaSparkContext(conf);
        sc.setLogLevel("WARN");
        SparkCalls calls = new SparkCalls(sc, master, settings, progress);
        if (!master.startsWith("local")) {
            awaitExecutors(calls, sc, master, settings.registrationSeconds(), settings.settleSeconds());
        }
        progress.println("spark: " + calls.describe());
        return calls;
    }

    /** Refuses a standalone master whose port does not answer, before Spark spends a minute retrying it. */
    private static void probe(String master, String host, int port) {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress(host, port), PROBE_MILLIS);
        } catch (IOException e) {
            throw new IllegalArgumentException("--master " + master + ": nothing answers at " + host + ":" + port
                    + " (start a cluster on this machine with scripts/spark-cluster start)");
        }
    }

    /** Waits for a first executor, then until no other has registered for {@code settle} seconds. */
    private static void awaitExecutors(SparkCalls calls, JavaSparkContext sc, String master, double seconds, double settle) {
        long deadline = System.nanoTime() + Math.round(seconds * 1e9);
        long settled = Long.MAX_VALUE;
        int seen = 0;
        while (System.nanoTime() < settled) {
            int now = calls.executors();
            if (now != seen) {
                seen = now;
                settled = System.nanoTime() + Math.round(settle * 1e9);
            }
            if (seen == 0 && System.nanoTime() > deadline) {
                sc.stop();
                throw new IllegalArgumentException(String.format(Locale.ROOT, "--master %s: no executor registered within %.0f s (are "
                        + "its workers up, with free cores and %s of memory? configs/spark.json registrationSeconds)", master, seconds,
                        sc.getConf().get("spark.executor.memory")));
            }
            try {
                Thread.sleep(100);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                sc.stop();
                throw new IllegalStateException("interrupted while waiting for executors", e);
            }
        }
    }
}
