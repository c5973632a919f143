package handsim.rollout;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The thread pool of rollouts: results in index order whatever the workers, failures rethrown. */
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
}
