package handsim.app;

/**
 * A run that could not do its job, for a reason its message says in one line (demo giving up
 * after throw-ins that were never caught): exit status 1.
 */
final class RunFailed extends RuntimeException {
    private static final long serialVersionUID = 1L;

    RunFailed(String message) {
        super(message);
    }
}
