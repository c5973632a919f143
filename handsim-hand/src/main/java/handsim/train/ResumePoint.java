package handsim.train;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.learn.Checkpoints;
import handsim.learn.DdpgAgent;
import handsim.learn.EpisodeStats;
import handsim.learn.MetricsCsv;
import handsim.learn.Trainer;
import handsim.learn.LearnerConfig;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.Consumer;
import java.util.stream.Stream;

/**
 * Where a resumed training run goes on from ({@link TrainRun#resume}): its checkpoint, or, when
 * that is lost and the user asks, the newest intact of the checkpoint before it and the policy
 * snapshots.
 */
final class ResumePoint {

    private ResumePoint() {
    }

    /** Where a resume goes on from, in words, and the learner it gives. */
    record Found(String what, Trainer trainer) {
    }

    /**
     * The learner saved in {@code file}, which must belong to the run of {@code identity}
     * ({@link TrainRun#identity}): missing, {@link NoSuchFileException}; another run's, an {@link
     * IllegalArgumentException} naming the first field that differs; any other failure, {@link
     * Checkpoints.Damaged}. A checkpoint that records no identity (written before checkpoints
     * did) is taken with a note to {@code notes}.
     */
    static Trainer checkpoint(Path file, TrainConfig config, ObjectNode identity, Consumer<String> notes) throws IOException {
        Trainer trainer;
        try {
            trainer = Trainer.resume(file, config.learner());
        } catch (NoSuchFileException | Checkpoints.Damaged e) {
            throw e;
        } catch (IOException | RuntimeException e) { // intact zip, but a trainer state that does not fit the run
            throw new Checkpoints.Damaged(file, e);
        }
        JsonNode recorded = trainer.identity();
        if (recorded == null) {
            notes.accept(file + " records no run identity (an older checkpoint): its task, object and config are not checked");
            return trainer;
        }
        for (String field : List.of("task", "object", "config", "run")) {
            JsonNode was = recorded.get(field), is = identity.get(field);
            if (was == null || !was.equals(is)) {
                throw new IllegalArgumentException(file + " belongs to another run: its " + field + " is " + (was == null ? "missing" : was)
                        + ", this run's is " + is + (field.equals("config") ? " (SHA-256 of config.json)" : "")
                        + "; nothing was changed (a checkpoint copied from another run folder?)");
            }
        }
        return trainer;
    }

    /** Whether the run in {@code dir} got as far as a checkpoint (a checkpoint writes the policy and its snapshot). */
    static boolean everCheckpointed(Path dir) throws IOException {
        return Files.exists(dir.resolve(TrainRun.POLICY)) || Files.exists(dir.resolve(TrainRun.PREVIOUS_CHECKPOINT))
                || !snapshots(dir).isEmpty();
    }

    /** The newest intact earlier checkpoint, else the newest intact policy snapshot, else null. */
    static Found fallback(Path dir, TrainConfig config, ObjectNode identity, ThrowEnvFactory envs, Consumer<String> notes)
            throws IOException {
        try {
            Trainer t = checkpoint(dir.resolve(TrainRun.PREVIOUS_CHECKPOINT), config, identity, notes);
            return new Found(TrainRun.PREVIOUS_CHECKPOINT + " (episode " + t.episodes() + ")", t);
        } catch (NoSuchFileException e) {
            // no earlier checkpoint: try the snapshots
        } catch (Checkpoints.Damaged e) {
            notes.accept(e.getMessage() + ": skipped");
        }
        for (Path snapshot : snapshots(dir)) {
            try {
                return new Found(TrainRun.SNAPSHOTS + "/" + snapshot.getFileName() + " (episode "
                        + ThrowPolicyFile.load(snapshot).provenance().path("episodes").asLong() + ", with a new critic and an "
                        + "empty replay buffer: the rest of the run differs from the lost one)", fromSnapshot(dir, snapshot, config, envs));
            } catch (IOException | RuntimeException e) {
                notes.accept(new Checkpoints.Damaged(snapshot, e).getMessage() + ": skipped");
            }
        }
        return null;
    }

    /** The policy snapshots of a run, newest first. */
    private static List<Path> snapshots(Path dir) throws IOException {
        Path folder = dir.resolve(TrainRun.SNAPSHOTS);
        if (!Files.isDirectory(folder)) {
            return List.of();
        }
        try (Stream<Path> files = Files.list(folder)) {
            return files.filter(f -> f.getFileName().toString().matches("episode-\\d+\\.json"))
                    .sorted(Comparator.comparing(Path::getFileName).reversed()).toList();
        }
    }

    /**
     * The learner of a run going on from a policy snapshot: the snapshot's actor and observation
     * statistics (counting as the decisions played), the run's episodes, decisions, moving average
     * and wall time as they stood at the snapshot (from its provenance and metrics.csv).
     */
    private static Trainer fromSnapshot(Path dir, Path snapshot, TrainConfig config, ThrowEnvFactory envs) throws IOException {
        ThrowPolicyFile f = ThrowPolicyFile.load(snapshot);
        Json p = Json.of(snapshot + "!provenance", f.provenance());
        long episodes = p.longValue("episodes"), decisions = p.longValue("decisions");
        if (!f.task().equals(envs.task()) || !f.object().equals(envs.object().name()) || f.state() != envs.state().encoding()) {
            throw new IllegalArgumentException("it is a policy of the " + f.task() + " task with a " + f.object()
                    + ", not of this run");
        }
        LearnerConfig l = config.learner();
        DdpgAgent agent = Warmstart.seededAgent(l, envs.observationSize(), handsim.control.ThrowParameters.SIZE);
        agent.startActorFrom(f.policy(), Math.max(2, decisions));
        List<EpisodeStats> rows = new ArrayList<>();
        Path metrics = dir.resolve(TrainRun.METRICS);
        if (Files.isRegularFile(metrics)) {
            for (EpisodeStats s : MetricsCsv.read(metrics, w -> { })) {
                if (s.episode() <= episodes) {
                    rows.add(s);
                }
            }
        }
        return Trainer.continueFrom(l, agent, episodes, decisions, rows.stream().map(EpisodeStats::reward).toList(),
                rows.isEmpty() ? 0 : rows.get(rows.size() - 1).wallSeconds());
    }
}
