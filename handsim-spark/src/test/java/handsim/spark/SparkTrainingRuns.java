package handsim.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.app.Main;
import handsim.config.Json;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

/**
 * {@code warmstart} and {@code dagger} through Spark against the thread pool, for ClusterCommandsTest
 * on a standalone cluster: a warm start's CMA-ES generation of throws gives the same searches and
 * dataset byte for byte, and the same pretrained actor; a DAgger round's episodes give the same
 * demonstrations (teacher labels and the teacher's trials) byte for byte, and the same fitted
 * actor. What differs is only what describes the run (its folder's name, command line, wall time).
 */
final class SparkTrainingRuns {

    private SparkTrainingRuns() {
    }

    private static Path onlyRun(Path runs) throws IOException {
        try (Stream<Path> list = Files.list(runs)) {
            return list.filter(Files::isDirectory).findFirst().orElseThrow();
        }
    }

    /** A policy file without what names its run (the provenance: run folder, command; the policy's note: run folder). */
    private static String policyWithoutProvenance(Path f) {
        ObjectNode o = (ObjectNode) Json.load(f).node();
        o.remove("provenance");
        if (o.get("policy") instanceof ObjectNode p) {
            p.remove("note");
        }
        return Json.pretty(o);
    }

    static String[] with(String[] base, String... more) {
        return Stream.concat(Stream.of(base), Stream.of(more)).toArray(String[]::new);
    }

    /** A short warm start (one CMA-ES generation of each of 2 searches; 2 is the fewest the warm start takes) on two threads and on {@code master}: the same bytes. */
    static void assertWarmStartOnSparkIsTheThreadPools(Path tmp, String master) throws Exception {
        // 2 initial conditions, 10 throws each: the start point, then one generation of λ = 9 (7 action entries)
        String[] warmstart = {"warmstart", "--config", "configs/train/flip-warmstart.json", "--set", "warmstart.initialConditions=2",
            "--set", "warmstart.keepReward=-100", "--set", "cmaes.maxEvaluations=10", "--set", "pretrain.epochs=2"};
        assertEquals(0, Main.run(with(warmstart, "--runs", tmp.resolve("threads").toString(), "--set", "run.workers=2")));
        assertEquals(0, Main.run(with(warmstart, "--runs", tmp.resolve("spark").toString(), "--master", master)));
        Path a = onlyRun(tmp.resolve("threads")), b = onlyRun(tmp.resolve("spark"));
        for (String f : List.of("searches.json", "dataset.csv")) {
            assertEquals(-1L, Files.mismatch(a.resolve(f), b.resolve(f)), f + " byte for byte");
        }
        assertEquals(2, Json.load(a.resolve("searches.json")).elements().size());
        assertEquals(10, Json.load(a.resolve("searches.json")).elements().get(0).integer("evaluations"));
        assertEquals(policyWithoutProvenance(a.resolve("pretrained-policy.json")), policyWithoutProvenance(b.resolve("pretrained-policy.json")));
    }

    /** A DAgger round of 2 episodes labelled by the teacher, on two threads and on {@code master}: the same bytes. */
    static void assertDaggerRoundOnSparkIsTheThreadPools(Path tmp, String master) throws Exception {
        String[] dagger = {"dagger", "--config", "configs/train/flip-dagger.json", "--set", "dagger.rounds=1", "--set",
            "dagger.episodesPerRound=2", "--set", "dagger.maxDecisionsPerEpisode=2", "--set", "pretrain.epochs=2"};
        assertEquals(0, Main.run(with(dagger, "--runs", tmp.resolve("threads").toString(), "--set", "run.workers=2")));
        assertEquals(0, Main.run(with(dagger, "--runs", tmp.resolve("spark").toString(), "--master", master)));
        Path a = onlyRun(tmp.resolve("threads")), b = onlyRun(tmp.resolve("spark"));
        for (String f : List.of("demonstrations.csv", "demonstrations-trials.csv")) {
            assertEquals(-1L, Files.mismatch(a.resolve(f), b.resolve(f)), f + " byte for byte");
        }
        assertTrue(Files.readAllLines(a.resolve("demonstrations.csv")).size() >= 3, "labels of at least two decisions");
        assertEquals(policyWithoutProvenance(a.resolve("policies/round-00.json")), policyWithoutProvenance(b.resolve("policies/round-00.json")));
        List<String> ra = Files.readAllLines(a.resolve("rounds.csv")), rb = Files.readAllLines(b.resolve("rounds.csv"));
        assertEquals(ra.get(1).replaceAll(",[^,]*$", ""), rb.get(1).replaceAll(",[^,]*$", ""), "round 0's row but its wall time");
    }
}
