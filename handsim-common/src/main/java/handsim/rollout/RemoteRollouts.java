package handsim.rollout;

import com.fasterxml.jackson.databind.JsonNode;
import handsim.config.Json;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.function.Function;

/**
 * Rollouts on a cluster's executors ({@link RemoteCalls}), through the interface the thread pool
 * implements: rollout i of a run travels as a small description (the run's {@link PortableTask}
 * and i), the executor rebuilds the task and its worker's resource ({@link PortableResource})
 * once and returns the result as JSON, which this driver reads back and hands to the caller in
 * index order. A rollout is a pure function of its description, so the results are the ones
 * {@link LocalRollouts} gives, whatever the executors; a rollout the cluster runs again after a
 * lost executor gives the same result. Finished rollouts of a {@link RecordedTask}'s journal are
 * read back here, not run; the others are journaled here as they come: only the driver writes.
 *
 * <p>A run's task says how it travels: a {@link ShippableTask} carries its portable form; any
 * other task is shipped by the {@link Shipper} given (an evaluation, rebuilt from its recorded
 * spec), its results read with its {@link RecordedTask}'s reader.
 *
 * @param <W> what each worker owns
 */
public final class RemoteRollouts<W> implements Rollouts<W> {

    /** The portable form of a run that is not a {@link ShippableTask}. */
    @FunctionalInterface
    public interface Shipper<W> {

        /** Run number {@code ordinal} (0, 1, ... in the order this driver makes its runs) as it travels. */
        PortableTask<W> ship(int ordinal);
    }

    private final RemoteCalls calls;
    private final PortableResource<W> resource;
    private final String resourceKey;
    private final Shipper<W> shipper;
    private int runs;

    /** Rollouts on {@code calls}' executors, each worker's resource built there from {@code resource}; {@code shipper} may be null. */
    public RemoteRollouts(RemoteCalls calls, PortableResource<W> resource, Shipper<W> shipper) {
        this.calls = calls;
        this.resource = resource;
        this.resourceKey = PortableCall.key(resource);
        this.shipper = shipper;
    }

    @Override
    public int workers() {
        return calls.slots();
    }

    /** A run's portable form and how its JSON results read back. */
    private record Shipment<W, R>(PortableTask<W> portable, Function<JsonNode, R> read) {
    }

    @SuppressWarnings("unchecked")
    private <R> Shipment<W, R> shipment(RolloutTask<W, R> task, int ordinal) {
        if (task instanceof ShippableTask<W, R> s) {
            return new Shipment<>(s.portable(), s.read());
        }
        if (shipper != null && task instanceof RecordedTask<W, R> r) {
            return new Shipment<>(shipper.ship(ordinal), r.read());
        }
        throw new IllegalStateException("run " + ordinal + "'s rollouts have no portable form (" + task.getClass().getName()
                + "): they cannot run on a cluster");
    }

    @Override
    public <R> List<R> run(int count, RolloutTask<W, R> task, Listener<? super R> listener) {
        if (count < 0) {
            throw new IllegalArgumentException("count must be >= 0, got " + count);
        }
        Shipment<W, R> shipment = shipment(task, runs++);
        RecordedTask.Journal journal = journal(task);
        String taskKey = PortableCall.key(shipment.portable());
        Object[] results = new Object[count];
        List<CompletableFuture<JsonNode>> pending = new ArrayList<>(Collections.nCopies(count, null));
        int window = 2 * Math.max(1, calls.slots()); // enough in flight that no executor waits for the driver
        try (RemoteCalls.Batch batch = calls.batch(shipment.portable().what(), count)) {
            int submitted = 0;
            for (int i = 0; i < count; i++) {
                while (submitted < count && submitted - i < window) {
                    int k = submitted++;
                    Optional<JsonNode> earlier = journal == null ? Optional.empty() : journal.finished(k);
                    // a result is journaled as soon as it arrives, whatever the index order
                    pending.set(k, earlier.isPresent() ? CompletableFuture.completedFuture(earlier.get())
                            : batch.submit(new IndexCall<>(resource, resourceKey, shipment.portable(), taskKey, k)).thenApply(json -> {
                                JsonNode node = Json.parse(shipment.portable().label(k), json).node();
                                if (journal != null) {
                                    journal.append(k, node);
                                }
                                return node;
                            }));
                }
                R result = shipment.read().apply(await(pending.get(i)));
                pending.set(i, null);
                results[i] = result;
                listener.onResult(i, result);
            }
        }
        @SuppressWarnings("unchecked")
        List<R> out = (List<R>) Arrays.asList(results);
        return Collections.unmodifiableList(out);
    }

    /** The journal of a recorded task, also when it is a shippable task's local form; null for none. */
    private static RecordedTask.Journal journal(RolloutTask<?, ?> task) {
        if (task instanceof RecordedTask<?, ?> r) {
            return r.journal();
        }
        return task instanceof ShippableTask<?, ?> s ? journal(s.local()) : null;
    }

    private static JsonNode await(CompletableFuture<JsonNode> f) {
        try {
            return f.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new RemoteFailure("interrupted while waiting for the cluster", e);
        } catch (ExecutionException e) {
            throw e.getCause() instanceof RuntimeException r ? r : new RemoteFailure(e.getCause().getMessage(), e.getCause());
        }
    }

    /** Closes the cluster connection: these rollouts were its last user. */
    @Override
    public void close() {
        calls.close();
    }
}
