package handsim.rollout;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.Serializable;

/**
 * A run of rollouts in a form that travels to a cluster's executors: serialisable data only (the
 * run's configuration documents as JSON text, policies as bytes, seeds and parameters) from
 * which any JVM with handsim's classes rebuilds the task, its results as JSON. Rollout i is a
 * pure function of that data and i.
 *
 * @param <W> what each worker owns (built where it runs by a {@link PortableResource})
 */
public interface PortableTask<W> extends Serializable {

    /** The task, rebuilt in this JVM (an executor keeps it for the run's later rollouts). */
    RolloutTask<W, JsonNode> rebuild();

    /** What the rollouts are, plural, for progress lines: {@code "box tests"}. */
    String what();

    /** Rollout {@code index} in a few words, naming its seed: {@code "box test 12 (seed 1012)"}. */
    String label(int index);
}
