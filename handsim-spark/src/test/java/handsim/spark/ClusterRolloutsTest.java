package handsim.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.rollout.LocalRollouts;
import handsim.rollout.RemoteCalls;
import handsim.rollout.RemoteRollouts;
import handsim.rollout.Rollouts;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Rollouts on a real standalone cluster (a master and two workers of one core, started by
 * scripts/spark-cluster): the thread pool's results bit for bit, with handsim's classes read by
 * the executors from the driver's classpath.
 */
@Tag("slow")
@Tag("cluster")
class ClusterRolloutsTest {

    @Test
    void aClusterOfTwoWorkersGivesTheThreadPoolsResults() throws Exception {
        LocalSparkRolloutsTest.Gaussians task = new LocalSparkRolloutsTest.Gaussians(11, 0.25, -1);
        List<Double> local;
        try (Rollouts<LocalSparkRolloutsTest.Counter> pool = new LocalRollouts<>(1, LocalSparkRolloutsTest.Counter::new)) {
            local = pool.run(30, task.shippable());
        }
        ByteArrayOutputStream lines = new ByteArrayOutputStream();
        try (TestCluster cluster = TestCluster.start(2);
                RemoteCalls calls = new SparkBackend().connect(cluster.master(), "handsim test",
                        new PrintStream(lines, true, StandardCharsets.UTF_8))) {
            List<Double> remote = new RemoteRollouts<>(calls, new LocalSparkRolloutsTest.Counters(), null).run(30, task.shippable());
            for (int i = 0; i < 30; i++) {
                assertEquals(Double.doubleToRawLongBits(local.get(i)), Double.doubleToRawLongBits(remote.get(i)), "sum " + i);
            }
        }
        String out = lines.toString(StandardCharsets.UTF_8);
        assertTrue(out.contains("spark: 30 sums done in") && out.contains("on 2 executors"), out);
    }
}
