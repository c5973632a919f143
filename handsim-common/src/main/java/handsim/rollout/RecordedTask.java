package handsim.rollout;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Optional;
import java.util.function.Function;

/**
 * A rollout task whose results have a JSON form that reads back to the same result bit for bit
 * ({@code write}, {@code read}), and the journal that keeps the finished rollouts of a run, or
 * none. The journal lets a killed run skip what it finished; the JSON form is also how results
 * travel back from a cluster ({@link RemoteRollouts}), so a result read from a journal, from an
 * executor or made here is the same.
 *
 * @param <W> what each worker owns
 * @param <R> the result of one rollout
 */
public record RecordedTask<W, R>(RolloutTask<W, R> task, Function<R, JsonNode> write, Function<JsonNode, R> read, Journal journal)
        implements RolloutTask<W, R> {

    /** Where finished rollouts are kept: read back on a resume, appended as they finish. */
    public interface Journal {

        /** Rollout {@code index}'s result, if a killed run of the same command finished it (counted as read back). */
        Optional<JsonNode> finished(int index);

        /** Keeps rollout {@code index}'s result, on disk before it returns. */
        void append(int index, JsonNode result);
    }

    /** Reads finished rollouts back from the journal, runs the others and journals their results at once. */
    @Override
    public Rollout<R> prepare(W worker) {
        Rollout<R> rollout = task.prepare(worker);
        if (journal == null) {
            return rollout;
        }
        return i -> {
            Optional<JsonNode> earlier = journal.finished(i);
            if (earlier.isPresent()) {
                return read.apply(earlier.get());
            }
            R result = rollout.run(i);
            journal.append(i, write.apply(result));
            return result;
        };
    }
}
