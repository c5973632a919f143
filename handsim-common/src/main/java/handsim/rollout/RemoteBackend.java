package handsim.rollout;

import java.io.PrintStream;

/**
 * A cluster engine that runs {@link PortableCall}s, found with {@link java.util.ServiceLoader}
 * when a command is given a master: the module that implements it (handsim-spark) is on the
 * classpath only then, so the default path never loads a cluster's classes.
 */
public interface RemoteBackend {

    /** The engine in a word ("Apache Spark"). */
    String name();

    /**
     * Connects to the cluster of {@code master} as the application {@code application}, its
     * progress and failure lines to {@code progress}. A master it cannot use is refused with an
     * {@link IllegalArgumentException} naming it.
     */
    RemoteCalls connect(String master, String application, PrintStream progress);
}
