package handsim.rollout;

/**
 * Work that a cluster could not do: a call that failed on every attempt (its message names the
 * call, its number and seed, and why), or a cluster that stopped. The driver's run stops; what it
 * wrote stays, and the same command resumes it.
 */
public final class RemoteFailure extends RuntimeException {

    private static final long serialVersionUID = 1L;

    public RemoteFailure(String message, Throwable cause) {
        super(message, cause);
    }

    public RemoteFailure(String message) {
        super(message);
    }
}
