package handsim.rollout;

import java.io.Serializable;
import java.util.concurrent.CompletableFuture;

/**
 * Runs {@link PortableCall}s on other JVMs: the executors of a cluster, each call on whichever is
 * free, a call that is lost with its executor run again elsewhere. Opened by a {@link
 * RemoteBackend}; the driver (this JVM) submits, collects and alone writes the results.
 */
public interface RemoteCalls extends AutoCloseable {

    /** How many calls run at once: the executors' cores. */
    int slots();

    /** The cluster in a few words (master, executors, cores), for the first progress line. */
    String describe();

    /**
     * A group of {@code total} calls that the progress lines count: {@code what} names them in
     * the plural ("box tests"); the batch's last line says how many were retried and the time
     * that lost.
     */
    Batch batch(String what, int total);

    /** Stops the cluster's work for this driver; calls still running are cancelled. */
    @Override
    void close();

    /** Calls submitted together, for their progress lines. */
    interface Batch extends AutoCloseable {

        /**
         * Starts {@code call} on a free executor. The future completes with its result, or with a
         * {@link RemoteFailure} naming the call when it failed on every attempt the cluster
         * allows.
         */
        <R extends Serializable> CompletableFuture<R> submit(PortableCall<R> call);

        /** Ends the batch with its summary line; its calls still running are cancelled. */
        @Override
        void close();
    }
}
