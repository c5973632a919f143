package handsim.rollout;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.function.Function;

/**
 * A rollout task with the form it travels in: this JVM's workers run {@code local} (sharing the
 * driver's parsed configs and environments), a cluster's executors rebuild {@code portable}, and
 * {@code read} turns the JSON they return into the result {@code local} gives.
 *
 * @param <W> what each worker owns
 * @param <R> the result of one rollout
 */
public record ShippableTask<W, R>(RolloutTask<W, R> local, PortableTask<W> portable, Function<JsonNode, R> read)
        implements RolloutTask<W, R> {

    @Override
    public Rollout<R> prepare(W worker) {
        return local.prepare(worker);
    }
}
