package handsim.app;

import handsim.evaluation.ResultJson;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.ThrowParameters;
import handsim.math.Vec3;
import handsim.task.LoopRecord;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** evaluate's per-episode resume: a run killed half-way, run again, ends as an uninterrupted run; and its provenance. */
@Tag("slow")
class EvaluateResumeTest {

    @Test
    void aLoopRecordReadsBackFromJsonBitForBit() {
        LoopRecord r = new LoopRecord(3, false, 1.2345678901234567, new Vec3(0.1, -0.2, 1e-300), Double.NaN,
                new ThrowParameters(new Vec3(0.01, 0.25, -0.003), new Vec3(0.3, 1 / 3.0, -0.7), 0.11), true, Double.POSITIVE_INFINITY,
                Math.PI, Double.NaN, 0.5, 0.25, null, Double.NaN, 2e-3, 0.0, 0.97, 1.4);
        assertEquals(r, ResultJson.loop(Json.parse("test", ResultJson.loop(r).toString()).node()));
    }

    @Test
    void aKilledEvaluationRunAgainRunsOnlyTheUnfinishedEpisodesAndEndsAsAnUninterruptedRun(@TempDir Path dir) throws Exception {
        String[] options = {"--task", "height", "--episodes", "4", "--loops", "2", "--seed", "31", "--workers", "1"};
        // the interrupted run, in a JVM of its own, killed once its first episode is journaled
        Path killed = dir.resolve("killed.json"), journal = dir.resolve("killed.json.episodes.jsonl");
        List<String> child = new java.util.ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), "-Dhandsim.home=" + Home.root(), "handsim.app.Main", "evaluate"));
        child.addAll(List.of(options));
        child.addAll(List.of("--json", killed.toString()));
        Process p = new ProcessBuilder(child).redirectErrorStream(true).redirectOutput(dir.resolve("child.log").toFile()).start();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (journaledEpisodes(journal) < 1 && p.isAlive() && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        p.destroyForcibly().waitFor();
        int before = journaledEpisodes(journal);
        assertTrue(before >= 1 && before < 4, "killed after 1 to 3 of 4 episodes: " + before + "\n" + Files.readString(dir.resolve("child.log")));
        assertFalse(Files.exists(killed), "no summary from a killed run");

        String text = run(concat(options, "--json", killed.toString()));
        assertTrue(text.contains("resuming: " + before + " finished episodes"), text);
        assertFalse(Files.exists(journal), "the journal goes once the results are written");
        Path whole = dir.resolve("whole.json");
        run(concat(options, "--json", whole.toString()));

        JsonNode resumed = Json.load(killed).node(), uninterrupted = Json.load(whole).node();
        assertEquals(before, resumed.get("episodes_resumed").asInt());
        assertEquals(0, uninterrupted.get("episodes_resumed").asInt());
        assertEquals(results(uninterrupted), results(resumed), "the same episodes, bit for bit");
        // provenance: the commit, the command line, and a hash of every config read
        JsonNode provenance = resumed.get("provenance");
        assertTrue(provenance.get("command").asText().startsWith("scripts/handsim evaluate --task height"), provenance.toString());
        assertEquals(handsim.config.ReadLog.sha256(Files.readAllBytes(Home.resolve("configs/sim.json"))),
                provenance.get("files").get("configs/sim.json").asText());
        assertTrue(provenance.get("files").has("models/arm_hand.json") && provenance.has("commit"), provenance.toString());
        // both runs were the same code: every one of the 4 episodes counted under the run's commit
        JsonNode byCommit = provenance.get("episodes_by_commit");
        assertEquals(1, byCommit.size(), byCommit.toString());
        assertEquals(4, byCommit.get(provenance.get("commit").asText()).asInt(), byCommit.toString());
    }

    /** The summary without what differs between runs of the same episodes: wall time, resumed count, provenance. */
    private static JsonNode results(JsonNode summary) {
        ObjectNode o = summary.deepCopy();
        o.remove(List.of("wall_s", "episodes_resumed", "provenance"));
        return o;
    }

    private static int journaledEpisodes(Path journal) throws java.io.IOException {
        if (!Files.exists(journal)) {
            return 0;
        }
        // the first line is the signature; a line is an episode once it is whole
        String text = Files.readString(journal);
        int lines = (int) text.chars().filter(c -> c == '\n').count();
        return Math.max(0, lines - 1);
    }

    private static String[] concat(String[] a, String... b) {
        String[] out = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }

    private static String run(String... args) {
        PrintStream stdout = System.out;
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        int code;
        try {
            System.setOut(new PrintStream(printed, true, StandardCharsets.UTF_8));
            String[] full = new String[args.length + 1];
            full[0] = "evaluate";
            System.arraycopy(args, 0, full, 1, args.length);
            code = Main.run(full);
        } finally {
            System.setOut(stdout);
        }
        String text = printed.toString(StandardCharsets.UTF_8);
        assertEquals(0, code, text);
        return text;
    }
}
