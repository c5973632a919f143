package handsim.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.app.Main;
import handsim.config.Json;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code evaluate --master local[2]}: a short box evaluation (2 tests, the nominal controller)
 * through Spark in local mode writes the CSV and the success map of the same evaluation on the
 * thread pool byte for byte, and its JSON but for what describes the run (wall time, workers,
 * command line). The evaluation is rebuilt from its spec alone where the tests run. Slow (about 25
 * s for the two evaluations): the fast tests keep Spark's local mode in LocalSparkStudyTest.
 */
@Tag("slow")
class SparkEvaluationTest {

    static String[] box(Path dir, String name, String... more) {
        String[] base = {"evaluate", "--task", "box", "--controller", "nominal", "--tests", "2", "--seed", "31", "--json",
                dir.resolve(name + ".json").toString(), "--csv", dir.resolve(name + ".csv").toString()};
        String[] all = new String[base.length + more.length];
        System.arraycopy(base, 0, all, 0, base.length);
        System.arraycopy(more, 0, all, base.length, more.length);
        return all;
    }

    static void assertSameEvaluation(Path dir, String a, String b) throws Exception {
        assertEquals(SameBytes.evaluateResults(dir.resolve(a + ".json")), SameBytes.evaluateResults(dir.resolve(b + ".json")),
                "the JSON but wall_s, workers and provenance");
        assertEquals(-1L, Files.mismatch(dir.resolve(a + ".csv"), dir.resolve(b + ".csv")), "the CSV byte for byte");
        assertEquals(-1L, Files.mismatch(dir.resolve(a + ".png"), dir.resolve(b + ".png")), "the success map byte for byte");
    }

    @Test
    void aBoxEvaluationThroughSparkIsTheThreadPools(@TempDir Path dir) throws Exception {
        assertEquals(0, Main.run(box(dir, "threads", "--workers", "2")));
        assertEquals(0, Main.run(box(dir, "spark", "--master", "local[2]")));
        assertSameEvaluation(dir, "threads", "spark");
        Json spark = Json.load(dir.resolve("spark.json"));
        assertEquals(2, spark.integer("tests"));
        assertTrue(spark.get("provenance").string("command").contains("--master local[2]"), "the command line is recorded as given");
    }
}
