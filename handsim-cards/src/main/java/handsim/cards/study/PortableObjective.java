package handsim.cards.study;

import java.io.Serializable;

/**
 * An objective in a form that travels to a cluster's executors: serialisable data only (the
 * sleight's configuration documents as read, as JSON text) from which any JVM with handsim's
 * classes builds the objective. Built once per executor and kept ({@link RemoteTrials}): a
 * sleight's hold, simulated once, serves every trial there.
 */
public interface PortableObjective extends Serializable {

    /** The objective, built in this JVM. */
    Objective build();
}
