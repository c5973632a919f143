package handsim.rollout;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Supplier;

/**
 * What an executor JVM keeps between the calls of a run: each task rebuilt once, each worker's
 * resource (a simulator) built once and lent to one call at a time, each worker's prepared
 * rollout runner. A few recent tasks are kept (a DAgger round, a warm-start generation, is a task
 * of its own); the runners of a task dropped go with it. Keys are the driver's hashes of the
 * serialised descriptions, so equal descriptions share what was built.
 */
final class ExecutorCache {

    /** Tasks kept: the run's current one and the ones just before it. */
    private static final int TASKS_KEPT = 4;

    private static final Map<String, RolloutTask<?, JsonNode>> TASKS = new LinkedHashMap<>(8, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, RolloutTask<?, JsonNode>> eldest) {
            boolean drop = size() > TASKS_KEPT;
            if (drop) {
                RUNNERS.values().forEach(byTask -> byTask.remove(eldest.getKey()));
            }
            return drop;
        }
    };
    private static final Map<String, Deque<Object>> IDLE = new HashMap<>();
    private static final Map<Object, Map<String, RolloutTask.Rollout<JsonNode>>> RUNNERS = new IdentityHashMap<>();

    private ExecutorCache() {
    }

    @SuppressWarnings("unchecked")
    static <W> String run(IndexCall<W> call) {
        W worker = borrow(call.resourceKey(), call.resource()::create);
        try {
            RolloutTask.Rollout<JsonNode> runner;
            synchronized (ExecutorCache.class) {
                runner = RUNNERS.computeIfAbsent(worker, w -> new HashMap<>()).get(call.taskKey());
            }
            if (runner == null) {
                RolloutTask<W, JsonNode> task = (RolloutTask<W, JsonNode>) task(call.taskKey(), call.task()::rebuild);
                runner = task.prepare(worker);
                synchronized (ExecutorCache.class) {
                    RUNNERS.get(worker).put(call.taskKey(), runner);
                }
            }
            return runner.run(call.index()).toString();
        } finally {
            giveBack(call.resourceKey(), worker);
        }
    }

    private static synchronized RolloutTask<?, JsonNode> task(String key, Supplier<? extends RolloutTask<?, JsonNode>> rebuild) {
        return TASKS.computeIfAbsent(key, k -> rebuild.get());
    }

    @SuppressWarnings("unchecked")
    private static <W> W borrow(String key, Supplier<W> create) {
        synchronized (ExecutorCache.class) {
            Deque<Object> idle = IDLE.get(key);
            if (idle != null && !idle.isEmpty()) {
                return (W) idle.pop();
            }
        }
        return create.get(); // built outside the lock: another call may build its own meanwhile
    }

    private static synchronized void giveBack(String key, Object worker) {
        IDLE.computeIfAbsent(key, k -> new ArrayDeque<>()).push(worker);
    }
}
