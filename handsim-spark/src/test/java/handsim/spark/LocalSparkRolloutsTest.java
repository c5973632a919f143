package handsim.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.DoubleNode;
import handsim.rollout.LocalRollouts;
import handsim.rollout.PortableResource;
import handsim.rollout.PortableTask;
import handsim.rollout.RecordedTask;
import handsim.rollout.RemoteCalls;
import handsim.rollout.RemoteRollouts;
import handsim.rollout.RolloutTask;
import handsim.rollout.Rollouts;
import handsim.rollout.ShippableTask;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.SplittableRandom;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Rollouts through Spark in local mode ({@code local[2]}: the driver's own threads as executors),
 * against the thread pool: the same results bit for bit, in index order; a rollout that throws
 * stops the run with its own exception; a journal's finished rollouts are read back, not run.
 * Slow: a second Spark context beside LocalSparkStudyTest's, which keeps local mode in the fast tests.
 */
@Tag("slow")
class LocalSparkRolloutsTest {

    private static final ByteArrayOutputStream LINES = new ByteArrayOutputStream();
    private static RemoteCalls calls;

    @BeforeAll
    static void connect() {
        calls = new SparkBackend().connect("local[2]", "handsim test", new PrintStream(LINES, true, StandardCharsets.UTF_8));
    }

    @AfterAll
    static void disconnect() {
        if (calls != null) {
            calls.close();
        }
    }

    /** A worker's resource: a counter of the rollouts it ran (so reuse across rollouts is visible, and harmless). */
    static final class Counter {
        int runs;
    }

    record Counters() implements PortableResource<Counter> {
        @Override
        public Counter create() {
            return new Counter();
        }
    }

    /**
     * Rollout i: a sum of 1000 seeded gaussians scaled by {@code scale}, a result that any change
     * of seed or order of operations would change in its last bits; index {@code failing} throws.
     */
    record Gaussians(long seed, double scale, int failing) implements PortableTask<Counter> {
        @Override
        public RolloutTask<Counter, JsonNode> rebuild() {
            return worker -> i -> DoubleNode.valueOf(value(worker, i));
        }

        double value(Counter worker, int i) {
            worker.runs++;
            if (i == failing) {
                throw new IllegalStateException("rollout " + i + " diverged");
            }
            SplittableRandom r = new SplittableRandom(seed + i);
            double s = 0;
            for (int k = 0; k < 1000; k++) {
                s += scale * Math.sin(r.nextDouble() * 7) * Math.exp(-r.nextDouble());
            }
            return s;
        }

        ShippableTask<Counter, Double> shippable() {
            return new ShippableTask<>(worker -> i -> value(worker, i), this, JsonNode::doubleValue);
        }

        @Override
        public String what() {
            return "sums";
        }

        @Override
        public String label(int index) {
            return "sum " + index + " (seed " + (seed + index) + ")";
        }
    }

    @Test
    void sparkGivesTheThreadPoolsResultsBitForBitInIndexOrder() {
        Gaussians task = new Gaussians(42, 1.0 / 3, -1);
        List<Double> local;
        try (Rollouts<Counter> pool = new LocalRollouts<>(2, Counter::new)) {
            local = pool.run(40, task.shippable());
        }
        List<Integer> order = new ArrayList<>();
        List<Double> remote = new RemoteRollouts<>(calls, new Counters(), null).run(40, task.shippable(), (i, r) -> order.add(i));
        for (int i = 0; i < 40; i++) {
            // bit for bit: the JSON a result travels in reads back to the same double
            assertEquals(Double.doubleToRawLongBits(local.get(i)), Double.doubleToRawLongBits(remote.get(i)), "sum " + i);
        }
        assertEquals(40, order.size());
        for (int i = 0; i < 40; i++) {
            assertEquals(i, order.get(i), "the listener sees results in index order");
        }
        String out = LINES.toString(StandardCharsets.UTF_8);
        assertTrue(out.contains("spark: 40 sums done in"), out);
    }

    @Test
    void aRolloutThatThrowsStopsTheRunWithItsExceptionAndItsLabel() {
        Gaussians task = new Gaussians(7, 1, 5);
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> new RemoteRollouts<>(calls, new Counters(), null).run(12, task.shippable()));
        assertEquals("rollout 5 diverged", e.getMessage());
        assertTrue(LINES.toString(StandardCharsets.UTF_8).contains("spark: sum 5 (seed 12) failed on executor"),
                "the failed call is named, with its seed, in one line");
    }

    @Test
    void aJournalsFinishedRolloutsAreReadBackAndTheOthersJournaledOnArrival() {
        Gaussians task = new Gaussians(3, 2, 4); // rollout 4 would throw: it must come from the journal
        Map<Integer, JsonNode> kept = new HashMap<>();
        kept.put(4, DoubleNode.valueOf(-1.5));
        RecordedTask.Journal journal = new RecordedTask.Journal() {
            @Override
            public synchronized Optional<JsonNode> finished(int index) {
                return Optional.ofNullable(kept.get(index));
            }

            @Override
            public synchronized void append(int index, JsonNode result) {
                kept.put(index, result);
            }
        };
        RecordedTask<Counter, Double> recorded = new RecordedTask<>(worker -> i -> task.value(worker, i), DoubleNode::valueOf,
                JsonNode::doubleValue, journal);
        List<Double> results = new RemoteRollouts<Counter>(calls, new Counters(), ordinal -> task).run(8, recorded);
        assertEquals(-1.5, results.get(4), 0.0, "read back from the journal");
        assertEquals(8, kept.size(), "every rollout journaled");
        assertEquals(task.value(new Counter(), 6), results.get(6), 0.0);
    }
}
