package handsim.cards.study;

import handsim.config.Json;
import handsim.report.Stop;
import handsim.rollout.PortableCall;
import handsim.rollout.RemoteCalls;
import handsim.rollout.RemoteFailure;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * A study's trials on a cluster's executors ({@link RemoteCalls}): each trial travels as its
 * number, parameters, the study's config and the objective's {@link PortableObjective} form; its
 * record comes back as JSON and is read back bit for bit. The study (on the driver) still
 * suggests every trial from the trials before it and alone writes the study's files, so the
 * trials are those of a run on this JVM's threads, whatever the executors and their speed; a
 * trial run again after a lost executor gives the same record.
 */
public final class RemoteTrials implements TrialExecutor {

    private final RemoteCalls calls;
    private final RemoteCalls.Batch batch;
    private final PortableObjective objective;
    private final String objectiveKey;
    private final String config;
    private final StudyConfig studyConfig;
    private final long seed;
    private final LinkedBlockingQueue<CompletableFuture<String>> finished = new LinkedBlockingQueue<>();

    /** Trials of a study of {@code config} and {@code seed} on {@code calls}; {@code expected}: how many this run will start. */
    public RemoteTrials(RemoteCalls calls, PortableObjective objective, StudyConfig config, long seed, int expected) {
        this.calls = calls;
        this.objective = objective;
        this.objectiveKey = PortableCall.key(objective);
        this.studyConfig = config;
        this.config = config.toJson().toString();
        this.seed = seed;
        this.batch = calls.batch("trials", expected);
    }

    /** As many at once as the study's parallelTrials: the cluster queues what its cores cannot start yet. */
    @Override
    public int slots() {
        return studyConfig.parallelTrials();
    }

    @Override
    public String describe() {
        return calls.describe();
    }

    @Override
    public void start(int number, double[] params) {
        CompletableFuture<String> f = batch.submit(new TrialCall(objective, objectiveKey, config, seed, number, params.clone()));
        f.whenComplete((record, failure) -> finished.add(f));
    }

    @Override
    public TrialRecord next() throws InterruptedException {
        CompletableFuture<String> f;
        while ((f = finished.poll(Study.STOP_POLL_MILLIS, TimeUnit.MILLISECONDS)) == null) {
            if (Stop.requested()) {
                return null;
            }
        }
        try {
            return TrialRecord.fromJson(Json.parse("a trial's record from the cluster", f.get()), studyConfig);
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            throw cause instanceof RuntimeException r ? r : new RemoteFailure(String.valueOf(cause.getMessage()), cause);
        }
    }

    @Override
    public void close() {
        batch.close();
    }
}
