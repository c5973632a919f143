package handsim.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.app.Main;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.apache.spark.SparkContext;
import org.apache.spark.SparkContext$;
import org.apache.spark.SparkExecutorInfo;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;

/**
 * A Card Snapping study on a standalone cluster of a master and two one-core workers started by
 * scripts/spark-cluster (reduced fingertips, 0.2 s trials, 4 trials, two at once) gives the
 * trial files of the same study on this JVM's threads, byte for byte but for the wall times the
 * trials measured, when its driver is killed and the same command resumes it, and when a worker
 * is killed mid-study (the cluster runs its trial again and says what that lost). The other
 * commands on a cluster are {@link ClusterCommandsTest}'s, on a cluster of their own, so that the
 * two classes can run at once. The cluster is stopped after the tests, also when they fail.
 */
@Tag("slow")
@Tag("cluster")
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class ClusterFaultsTest {

    private static final Path CONFIG = Path.of("handsim-spark/src/test/resources/cluster/short-snap-study.json");
    /** What the comparison leaves out: study.json records each run's command line (--master among it). */
    private static final List<String> RUN_RECORDS = List.of("study.json");

    /** Trials of the study: the config's 3 random start-up trials, then one of TPE's. */
    private static final int TRIALS = 4;

    private static TestCluster cluster;
    private static Path local;

    @TempDir
    static Path tmp;

    private static List<String> study(Path out, String... more) {
        List<String> args = new ArrayList<>(List.of("cards", "optimize", "--sleight", "snap", "--trials", Integer.toString(TRIALS), "--seed", "4", "--mesh",
                "reduced", "--no-frames", "--config", CONFIG.toString(), "--set", "snap.trial.duration=0.2", "--set", "snap.params.t1=0.05", "--set",
                "snap.params.t2=0.07", "--set", "snap.params.t3=0.13", "--out", out.toString()));
        args.addAll(List.of(more));
        return args;
    }

    @BeforeAll
    static void startClusterAndRunTheStudyLocally() throws Exception {
        cluster = TestCluster.start(2);
        local = tmp.resolve("local");
        assertEquals(0, Main.run(study(local, "--workers", "2").toArray(String[]::new)), "the local study");
    }

    @AfterAll
    static void stopCluster() {
        if (cluster != null) {
            cluster.close();
        }
    }

    @Test
    @Order(0)
    void aKilledDriverResumesToTheSameTrials() throws Exception {
        Path remote = tmp.resolve("driver-killed");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), "-Dhandsim.home=" + Path.of("").toAbsolutePath(), Main.class.getName()));
        command.addAll(study(remote, "--master", cluster.master()));
        Process driver = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(tmp.resolve("driver.log").toFile()).start();
        try {
            awaitTrialFiles(remote, 2, driver);
        } finally {
            driver.descendants().forEach(ProcessHandle::destroyForcibly);
            driver.destroyForcibly().waitFor(30, TimeUnit.SECONDS); // kill -9: no shutdown hook, trials under way lost
        }
        int before = trialFiles(remote);
        assertTrue(before >= 2 && before < TRIALS, before + " trials finished when the driver was killed");
        assertEquals(0, Main.run(study(remote, "--master", cluster.master()).toArray(String[]::new)), "the same command resumes");
        SameBytes.assertSameFiles(local, remote, RUN_RECORDS);
    }

    @Test
    @Order(1)
    void aWorkerKilledMidStudyCostsTimeButNotTheResults() throws Exception {
        Path remote = tmp.resolve("worker-killed");
        ByteArrayOutputStream lines = new ByteArrayOutputStream();
        PrintStream console = System.out;
        int[] exit = {-1};
        Thread run = new Thread(() -> exit[0] = Main.run(study(remote, "--master", cluster.master()).toArray(String[]::new)));
        System.setOut(new PrintStream(new Tee(console, lines), true, StandardCharsets.UTF_8));
        try {
            run.start();
            awaitTrialFiles(remote, 1, null);
            awaitRunningTasks(2); // each one-core worker runs a trial now, so either worker's loss costs one
            cluster.killWorker(1);
            run.join(TimeUnit.MINUTES.toMillis(20));
        } finally {
            System.setOut(console);
        }
        assertEquals(0, exit[0], "the study finishes on the worker left");
        int files = SameBytes.assertSameFiles(local, remote, RUN_RECORDS);
        assertTrue(files >= TRIALS + 2, files + " files compared: the trials, best.json and history.png at least");
        Matcher lost = Pattern.compile("(\\d+) attempts lost with their executors and run again \\(([0-9.]+) s of executor time lost\\)")
                .matcher(lines.toString(StandardCharsets.UTF_8));
        assertTrue(lost.find(), "the batch's last line says what the lost worker cost");
        assertTrue(Integer.parseInt(lost.group(1)) >= 1 && Double.parseDouble(lost.group(2)) > 0, lost.group());
    }

    private static int trialFiles(Path study) throws IOException {
        Path trials = study.resolve("trials");
        if (!Files.isDirectory(trials)) {
            return 0;
        }
        try (Stream<Path> files = Files.list(trials)) {
            return (int) files.filter(f -> f.getFileName().toString().matches("trial-\\d+\\.json")).count();
        }
    }

    private static void awaitTrialFiles(Path study, int n, Process alive) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.MINUTES.toNanos(15);
        while (trialFiles(study) < n) {
            assertTrue(System.nanoTime() < deadline, "no " + n + " trials within 15 minutes");
            assertTrue(alive == null || alive.isAlive(), "the driver ended early: " + TestCluster.read(tmp.resolve("driver.log")));
            Thread.sleep(100);
        }
    }

    /**
     * Waits until the study's driver (this JVM's active Spark context) has {@code n} tasks running
     * on its executors. A trial takes seconds, so a worker killed right after still holds one.
     */
    private static void awaitRunningTasks(int n) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MINUTES.toNanos(5);
        while (runningTasks() < n) {
            assertTrue(System.nanoTime() < deadline, "no " + n + " tasks running at once within 5 minutes");
            Thread.sleep(20);
        }
    }

    private static int runningTasks() {
        scala.Option<SparkContext> active = SparkContext$.MODULE$.getActive();
        if (active.isEmpty()) {
            return 0;
        }
        int running = 0;
        for (SparkExecutorInfo executor : active.get().statusTracker().getExecutorInfos()) {
            running += executor.numRunningTasks();
        }
        return running;
    }

    /** Writes to two streams. */
    private static final class Tee extends java.io.OutputStream {
        private final java.io.OutputStream a;
        private final java.io.OutputStream b;

        Tee(java.io.OutputStream a, java.io.OutputStream b) {
            this.a = a;
            this.b = b;
        }

        @Override
        public synchronized void write(int c) throws IOException {
            a.write(c);
            b.write(c);
        }

        @Override
        public synchronized void write(byte[] buf, int off, int len) throws IOException {
            a.write(buf, off, len);
            b.write(buf, off, len);
        }
    }
}
