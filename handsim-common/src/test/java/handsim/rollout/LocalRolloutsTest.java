package handsim.rollout;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.report.Stop;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The thread pool of rollouts: results in index order whatever the workers, failures rethrown, a stop request heard at once. */
@Tag("fast")
class LocalRolloutsTest {

    @Test
    void resultsReachTheListenerInIndexOrderWithAnyNumberOfWorkers() {
        for (int workers : new int[] {1, 2, 3}) {
            List<Integer> order = new ArrayList<>();
            try (Rollouts<Object> rollouts = new LocalRollouts<>(workers, Object::new)) {
                // later indices finish first: the listener still sees 0, 1, 2, ...
                List<Integer> squares = rollouts.run(6, worker -> i -> {
                    java.util.concurrent.locks.LockSupport.parkNanos(5_000_000L * (6 - i));
                    return i * i;
                }, (i, r) -> order.add(i));
                assertEquals(List.of(0, 1, 4, 9, 16, 25), squares, workers + " workers");
            }
            assertEquals(List.of(0, 1, 2, 3, 4, 5), order, workers + " workers");
        }
    }

    @Test
    void aFailingRolloutStopsTheRunAndIsRethrown() {
        try (Rollouts<Object> rollouts = new LocalRollouts<>(2, () -> null)) {
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> rollouts.run(10, sim -> i -> {
                if (i == 3) {
                    throw new IllegalStateException("rollout 3 failed");
                }
                return i;
            }));
            assertEquals("rollout 3 failed", e.getMessage());
            assertEquals(List.of(0, 1, 2, 3, 4), rollouts.run(5, sim -> i -> i), "the workers are usable after a failure");
        }
    }

    @Test
    void aStopRequestEndsTheRunAtOnceWithoutWaitingForTheRolloutsUnderWay() {
        try (Rollouts<Object> rollouts = new LocalRollouts<>(2, Object::new)) {
            long t0 = System.nanoTime();
            Stop.Stopped stopped = assertThrows(Stop.Stopped.class, () -> rollouts.run(4, worker -> i -> {
                if (i == 1) {
                    Stop.request("SIGTERM"); // as the signal handler does, while rollout 0 is still under way
                }
                java.util.concurrent.locks.LockSupport.parkNanos(i == 0 ? 3_000_000_000L : 0);
                return i;
            }));
            double seconds = (System.nanoTime() - t0) * 1e-9;
            // the caller looks for a request every 0.1 s: it is back well before rollout 0's 3 s are over
            assertTrue(seconds < 1.5, "stopped after " + seconds + " s");
            assertEquals(143, stopped.status(), "128 + SIGTERM's 15");
            assertTrue(stopped.getMessage().startsWith("stopped by SIGTERM: "), stopped.getMessage());
        } finally {
            Stop.reset();
        }
    }
}
