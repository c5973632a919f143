package handsim.rollout;

/**
 * Rollout {@code index} of a portable task, as one call to a cluster: the executor rebuilds the
 * task and the worker's resource once (kept by {@link ExecutorCache} under the driver's keys,
 * hashes of their serialised forms) and returns the rollout's result as JSON text.
 */
record IndexCall<W>(PortableResource<W> resource, String resourceKey, PortableTask<W> task, String taskKey, int index)
        implements PortableCall<String> {

    private static final long serialVersionUID = 1L;

    @Override
    public String call() {
        return ExecutorCache.run(this);
    }

    @Override
    public String label() {
        return task.label(index);
    }
}
