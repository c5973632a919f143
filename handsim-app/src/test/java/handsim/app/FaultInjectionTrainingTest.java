package handsim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import com.fasterxml.jackson.databind.JsonNode;
import handsim.config.Home;
import handsim.config.Json;
import handsim.learn.EpisodeStats;
import handsim.learn.MetricsCsv;
import handsim.train.TrainRun;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Faults injected into training runs: a checkpoint missing, truncated or without its state, a
 * partial last row of metrics.csv, and a JVM killed while it writes a checkpoint. Each case
 * asserts the exit status, the message and the files left behind. The runs are tiny (3 episodes
 * of one throw, a checkpoint after every episode); training is deterministic, so a run
 * that resumed ends exactly (bit for bit) like the uninterrupted {@link #reference} run.
 */
@Tag("slow")
class FaultInjectionTrainingTest {

    private static final String[] TINY = {"--set", "training.episodes=3", "--set", "training.parallelEpisodes=1",
        "--set", "training.maxDecisionsPerEpisode=1", "--set", "training.checkpointEveryEpisodes=1",
        "--set", "exploration.warmupSteps=1", "--set", "ddpg.batchSize=2", "--set", "ddpg.replayCapacity=100",
        "--set", "run.workers=1"};

    @TempDir
    static Path tmp;
    /** The tiny run, uninterrupted. */
    private static Path reference;
    /** The same run stopped after 2 episodes (checkpoints after episodes 1 and 2): copied for each fault. */
    private static Path stopped;

    @BeforeAll
    static void runs() throws IOException {
        reference = train(tmp.resolve("reference"));
        stopped = train(tmp.resolve("stopped"), "--session-episodes", "2");
        assertEquals(2, MetricsCsv.read(stopped.resolve(TrainRun.METRICS)).size());
        assertTrue(Files.isRegularFile(stopped.resolve(TrainRun.PREVIOUS_CHECKPOINT)), "the checkpoint before the last is kept");
    }

    private static Path train(Path runs, String... more) throws IOException {
        List<String> args = new ArrayList<>(List.of("train", "--config", "configs/train/height.json", "--runs", runs.toString()));
        args.addAll(List.of(TINY));
        args.addAll(List.of(more));
        CliRun r = CliRun.of(args.toArray(String[]::new));
        assertEquals(0, r.status(), r.toString());
        try (Stream<Path> dirs = Files.list(runs)) {
            return dirs.findFirst().orElseThrow();
        }
    }

    /** A copy of the stopped run to damage. */
    private static Path copyOfStopped(String name) throws IOException {
        return CliRun.copyTree(stopped, tmp.resolve("cases").resolve(name));
    }

    /** A copy of the finished reference run to damage. */
    private static Path copyOfReference(String name) throws IOException {
        return CliRun.copyTree(reference, tmp.resolve("cases").resolve(name));
    }

    /** {@code train --resume run} fails with status 2 and one line naming {@code parts}, and leaves every file as it was. */
    private static void assertResumeRefusedLeavingAllAsItWas(Path run, String... parts) throws IOException {
        Map<String, String> before = CliRun.contents(run);
        CliRun.of("train", "--resume", run.toString()).assertRefused(2, parts);
        assertEquals(before, CliRun.contents(run), "metrics, policy and snapshots untouched");
    }

    @Test
    void aResumeWithoutItsCheckpointIsRefusedAndChangesNothing() throws IOException {
        Path run = copyOfStopped("missing");
        Files.delete(run.resolve(TrainRun.CHECKPOINT));
        assertResumeRefusedLeavingAllAsItWas(run, "checkpoint.zip is missing", "--from-snapshot");
    }

    @Test
    void aTruncatedCheckpointIsRefusedAndChangesNothing() throws IOException {
        Path run = copyOfStopped("truncated");
        Path checkpoint = run.resolve(TrainRun.CHECKPOINT);
        byte[] whole = Files.readAllBytes(checkpoint);
        Files.write(checkpoint, java.util.Arrays.copyOf(whole, whole.length / 2));
        assertResumeRefusedLeavingAllAsItWas(run, "checkpoint.zip is damaged", "--from-snapshot");
    }

    @Test
    void aCheckpointWithoutItsStateIsRefusedAndChangesNothing() throws IOException {
        Path run = copyOfStopped("stateless");
        withoutEntry(run.resolve(TrainRun.CHECKPOINT), "state.json");
        assertResumeRefusedLeavingAllAsItWas(run, "checkpoint.zip is damaged", "state.json");
    }

    @Test
    void fromSnapshotGoesOnFromThePreviousCheckpointAndEndsLikeAnUninterruptedRun() throws IOException {
        Path run = copyOfReference("previous"); // its checkpoints: after episode 3, and the one before, after 2
        Files.writeString(run.resolve(TrainRun.CHECKPOINT), "not a zip");
        CliRun r = CliRun.of("train", "--resume", run.toString(), "--from-snapshot");
        assertEquals(0, r.status(), r.toString());
        assertTrue(r.out().contains("going on from checkpoint-previous.zip (episode 2)"), r.out());
        assertSameRun(reference, run);
        JsonNode fallback = Json.load(run.resolve(TrainRun.RUN_JSON)).node().get("fallbacks").get(0);
        assertTrue(fallback.get("from").asText().startsWith(TrainRun.PREVIOUS_CHECKPOINT), fallback.toString());
        assertEquals(List.of(), CliRun.temporaryFiles(run));
    }

    @Test
    void fromSnapshotWithNoCheckpointLeftGoesOnFromTheNewestPolicySnapshot() throws IOException {
        Path run = copyOfStopped("snapshot");
        List<EpisodeStats> before = MetricsCsv.read(run.resolve(TrainRun.METRICS));
        Files.delete(run.resolve(TrainRun.CHECKPOINT));
        Files.delete(run.resolve(TrainRun.PREVIOUS_CHECKPOINT));
        CliRun r = CliRun.of("train", "--resume", run.toString(), "--from-snapshot");
        assertEquals(0, r.status(), r.toString());
        assertTrue(r.out().contains("going on from policies/episode-00002.json (episode 2, with a new critic"), r.out());
        List<EpisodeStats> after = MetricsCsv.read(run.resolve(TrainRun.METRICS));
        assertEquals(3, after.size(), "the run reached its budget");
        assertEquals(before, after.subList(0, 2), "the episodes before the snapshot are kept as they were");
        // the episodes after the snapshot draw their seeds where the lost run would have: its decisions count on
        assertEquals(before.get(1).totalSteps() + after.get(2).decisions(), after.get(2).totalSteps());
        assertTrue(Files.isRegularFile(run.resolve("policies/episode-00003.json")));
        JsonNode fallback = Json.load(run.resolve(TrainRun.RUN_JSON)).node().get("fallbacks").get(0);
        assertEquals(2, fallback.get("episodes").asInt(), fallback.toString());
        assertTrue(fallback.get("because").asText().contains("missing"), fallback.toString());
    }

    @Test
    void aPartialLastMetricsRowIsDroppedWithAWarningAndTheRunEndsLikeAnUninterruptedOne() throws IOException {
        Path run = copyOfStopped("partial");
        Files.writeString(run.resolve(TrainRun.METRICS), "3,3,1,0.71", StandardOpenOption.APPEND); // a kill mid-append
        CliRun r = CliRun.of("train", "--resume", run.toString());
        assertEquals(0, r.status(), r.toString());
        List<String> warnings = r.err().lines().filter(l -> l.contains("warning")).toList();
        assertEquals(1, warnings.size(), r.err());
        assertTrue(warnings.get(0).contains("line 4 is a partial row") && warnings.get(0).contains("dropped"), r.err());
        assertSameRun(reference, run);
    }

    /**
     * A child JVM trains the tiny run and is killed (destroyForcibly: SIGKILL, no shutdown hooks)
     * while a write of its checkpoint is under way, seen by the temporary file it leaves. The
     * resumed run deletes the leftover and ends exactly like the uninterrupted run.
     */
    @Test
    void aRunKilledWhileWritingACheckpointResumesAndEndsLikeAnUninterruptedRun() throws Exception {
        Path runs = tmp.resolve("killed"), told = tmp.resolve("killed-run-dir.txt");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-XX:+UseSerialGC", "-Dhandsim.home=" + Home.root(), "-D" + TrainCommand.RUN_DIR_FILE_PROPERTY + "=" + told,
                "-Dorg.slf4j.simpleLogger.defaultLogLevel=warn", "-cp", System.getProperty("java.class.path"),
                Main.class.getName(), "train", "--config", "configs/train/height.json", "--runs", runs.toString()));
        command.addAll(List.of(TINY));
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(tmp.resolve("killed.log").toFile());
        pb.environment().put("OMP_NUM_THREADS", "1");
        Process child = pb.start();
        Path run = null;
        List<Path> leftover = List.of();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (leftover.isEmpty()) {
            if (!child.isAlive()) {
                fail("the child finished (status " + child.exitValue() + ") before a checkpoint write was caught: "
                        + Files.readString(tmp.resolve("killed.log")));
            }
            if (System.nanoTime() > deadline) {
                child.destroyForcibly();
                fail("no checkpoint write seen in 120 s");
            }
            if (run == null && Files.exists(told) && Files.size(told) > 0) {
                run = Path.of(Files.readString(told));
            }
            if (run != null && Files.exists(run.resolve(TrainRun.CONFIG))) {
                leftover = inFlight(run);
            }
        }
        child.destroyForcibly();
        assertTrue(child.waitFor(30, TimeUnit.SECONDS), "killed");
        assertFalse(CliRun.temporaryFiles(run).isEmpty(), "killed mid-write: " + leftover);
        CliRun r = CliRun.of("train", "--resume", run.toString());
        assertEquals(0, r.status(), r.toString());
        assertEquals(List.of(), CliRun.temporaryFiles(run), "the killed write's temporary file is gone");
        assertSameRun(reference, run);
    }

    /**
     * The temporary files of a checkpoint's writes under way in a run folder: the learner, the
     * checkpoint before it, the policy and its snapshot, the curves (not the metrics, config or
     * provenance, which a run writes at its start).
     */
    private static List<Path> inFlight(Path run) {
        try {
            return CliRun.temporaryFiles(run).stream().filter(f -> !f.getFileName().toString().matches(
                    "\\.(metrics\\.csv|config\\.json|run\\.json)\\..*")).toList();
        } catch (IOException | java.io.UncheckedIOException e) { // a file moved away while listed
            return List.of();
        }
    }

    /** The two runs have the same episodes and the same final actor, bit for bit (wall times aside). */
    private static void assertSameRun(Path expected, Path actual) throws IOException {
        List<EpisodeStats> a = MetricsCsv.read(expected.resolve(TrainRun.METRICS)), b = MetricsCsv.read(actual.resolve(TrainRun.METRICS));
        assertEquals(a.size(), b.size());
        for (int i = 0; i < a.size(); i++) {
            assertEquals(withoutWallTime(a.get(i)), withoutWallTime(b.get(i)), "episode " + (i + 1));
        }
        assertTrue(a.get(a.size() - 1).updates() > 0, "the run learned: a resume that lost the learner would show");
        assertEquals(actor(expected), actor(actual), "the same actor");
    }

    /** The actor of a run's policy file: its layers and observation statistics (without the note naming the run). */
    private static JsonNode actor(Path run) {
        com.fasterxml.jackson.databind.node.ObjectNode policy = (com.fasterxml.jackson.databind.node.ObjectNode)
                Json.load(run.resolve(TrainRun.POLICY)).node().get("policy").deepCopy();
        policy.remove("note");
        return policy;
    }

    private static EpisodeStats withoutWallTime(EpisodeStats s) {
        return new EpisodeStats(s.episode(), s.totalSteps(), s.decisions(), s.reward(), s.averageReward(), s.q0(),
                s.criticLoss(), s.actorLoss(), s.updates(), s.terminal(), s.sigma(), 0);
    }

    /** Rewrites a zip without one of its entries. */
    private static void withoutEntry(Path zip, String name) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ZipInputStream in = new ZipInputStream(Files.newInputStream(zip)); ZipOutputStream out = new ZipOutputStream(bytes)) {
            for (ZipEntry e; (e = in.getNextEntry()) != null; ) {
                if (!e.getName().equals(name)) {
                    out.putNextEntry(new ZipEntry(e.getName()));
                    in.transferTo(out);
                    out.closeEntry();
                }
            }
        }
        try (OutputStream out = Files.newOutputStream(zip)) {
            bytes.writeTo(out);
        }
    }
}
