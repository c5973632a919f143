package handsim.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.app.Main;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import handsim.rollout.LocalRollouts;
import handsim.rollout.RemoteCalls;
import handsim.rollout.RemoteRollouts;
import handsim.rollout.Rollouts;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;

/**
 * Commands on a standalone cluster of a master and two one-core workers started by
 * scripts/spark-cluster, one cluster for all of them. Rollouts give the thread pool's results bit
 * for bit, with handsim's classes read by the executors from the driver's classpath. A short box
 * evaluation (2 tests) writes the JSON, CSV and success map of the same evaluation on this JVM's
 * threads, byte for byte but for what describes the run. A warm start's CMA-ES generation of
 * throws and a DAgger round's teacher labels give the thread pool's files too. A study whose
 * driver or worker is killed is {@link ClusterFaultsTest}'s, on a cluster of its own.
 * The cluster is stopped after the tests, also when they fail.
 */
@Tag("slow")
@Tag("cluster")
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class ClusterCommandsTest {

    private static TestCluster cluster;

    @TempDir
    static Path tmp;

    @BeforeAll
    static void startCluster() throws Exception {
        cluster = TestCluster.start(2);
    }

    @AfterAll
    static void stopCluster() {
        if (cluster != null) {
            cluster.close();
        }
    }

    @Test
    @Order(0)
    void rolloutsOnTwoWorkersGiveTheThreadPoolsResults() throws Exception {
        LocalSparkRolloutsTest.Gaussians task = new LocalSparkRolloutsTest.Gaussians(11, 0.25, -1);
        List<Double> local;
        try (Rollouts<LocalSparkRolloutsTest.Counter> pool = new LocalRollouts<>(1, LocalSparkRolloutsTest.Counter::new)) {
            local = pool.run(30, task.shippable());
        }
        ByteArrayOutputStream lines = new ByteArrayOutputStream();
        try (RemoteCalls calls = new SparkBackend().connect(cluster.master(), "handsim test", new PrintStream(lines, true, StandardCharsets.UTF_8))) {
            List<Double> remote = new RemoteRollouts<>(calls, new LocalSparkRolloutsTest.Counters(), null).run(30, task.shippable());
            for (int i = 0; i < 30; i++) {
                assertEquals(Double.doubleToRawLongBits(local.get(i)), Double.doubleToRawLongBits(remote.get(i)), "sum " + i);
            }
        }
        String out = lines.toString(StandardCharsets.UTF_8);
        assertTrue(out.contains("spark: 30 sums done in") && out.contains("on 2 executors"), out);
    }

    @Test
    @Order(1)
    void aBoxEvaluationOnTheClusterIsTheThreadPools() throws Exception {
        Path dir = tmp.resolve("box");
        String[] box = {"evaluate", "--task", "box", "--controller", "nominal", "--tests", "2", "--seed", "77"};
        assertEquals(0, Main.run(SparkTrainingRuns.with(box, "--workers", "2", "--json", dir.resolve("threads.json").toString(),
                "--csv", dir.resolve("threads.csv").toString())));
        assertEquals(0, Main.run(SparkTrainingRuns.with(box, "--master", cluster.master(), "--json", dir.resolve("cluster.json").toString(),
                "--csv", dir.resolve("cluster.csv").toString())));
        SparkEvaluationTest.assertSameEvaluation(dir, "threads", "cluster");
    }

    @Test
    @Order(2)
    void aWarmStartGenerationOnTheClusterIsTheThreadPools() throws Exception {
        SparkTrainingRuns.assertWarmStartOnSparkIsTheThreadPools(Files.createDirectories(tmp.resolve("warmstart")), cluster.master());
    }

    @Test
    @Order(3)
    void aDaggerRoundsTeacherLabelsOnTheClusterAreTheThreadPools() throws Exception {
        SparkTrainingRuns.assertDaggerRoundOnSparkIsTheThreadPools(Files.createDirectories(tmp.resolve("dagger")), cluster.master());
    }
}
