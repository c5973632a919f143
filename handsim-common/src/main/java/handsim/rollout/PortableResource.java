package handsim.rollout;

import java.io.Serializable;

/**
 * What a worker owns (a simulator), described by serialisable data (the model and physics
 * configuration as JSON text) and built where the worker runs.
 *
 * @param <W> the resource
 */
public interface PortableResource<W> extends Serializable {

    /** A new resource, built in this JVM. */
    W create();
}
