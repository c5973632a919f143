package handsim.spark;

import java.io.Serializable;

/**
 * What an executor sends back for a call: its result, or the exception it threw (a call that
 * throws is not retried: it would throw again), the time the call took there and the executor.
 *
 * @param nanos the call's own time on the executor, ns
 */
record Timed(Serializable value, Throwable failure, long nanos, String executor) implements Serializable {

    private static final long serialVersionUID = 1L;
}
