package handsim.app;

import handsim.rollout.RemoteBackend;
import handsim.rollout.RemoteCalls;
import java.util.ServiceLoader;
import picocli.CommandLine.Option;

/**
 * {@code --master}: the commands whose work is many independent runs (study trials, evaluation
 * episodes, warm-start candidates, teacher labels) run it on a cluster instead of this machine's
 * threads, with the same results. Under {@code spark-submit} the master it was given is used.
 * The cluster engine is found with {@link ServiceLoader} only when a master is given, so the
 * default path never loads it.
 */
final class ClusterOptions {

    @Option(names = "--master", paramLabel = "URL", description = "run on a cluster: spark://HOST:PORT (scripts/spark-cluster start "
            + "starts one on this machine), local[N], yarn or k8s://HOST:PORT; the results are those of a run without it "
            + "(default: this machine's threads, or spark-submit's master; docs/cluster.md)")
    String master;

    /** The master asked for: the option, or the one spark-submit gave; null for this machine's threads. */
    String master() {
        return master != null ? master : System.getProperty("spark.master");
    }

    boolean remote() {
        return master() != null;
    }

    /** Refuses an empty master before anything is written. */
    void validate() {
        if (master != null && master.isBlank()) {
            throw new IllegalArgumentException("--master must be a URL such as spark://HOST:PORT or local[2], got \"" + master + "\"");
        }
    }

    /** Connects to the cluster as {@code application}; refuses in one line when no engine is on the classpath. */
    RemoteCalls connect(String application) {
        validate();
        for (RemoteBackend backend : ServiceLoader.load(RemoteBackend.class)) {
            return backend.connect(master(), application, System.out);
        }
        throw new IllegalArgumentException("--master " + master() + ": no cluster engine on the classpath (scripts/handsim adds "
                + "handsim-spark and Spark when --master is given; with java -cp, add handsim-spark/target/classes and its "
                + "dependencies: mvn -pl handsim-spark -am package)");
    }
}
