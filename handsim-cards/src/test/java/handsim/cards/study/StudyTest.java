package handsim.cards.study;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.ConfigException;
import handsim.config.Json;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A study end to end on a cheap objective (Branin, plus an integer that costs 0.01 per step
 * away from 3): its folder, worker-count independence, and resuming after being stopped
 * half-way.
 */
@Tag("slow")
class StudyTest {

    private static final long SEED = 5;

    private static StudyConfig config(int parallelTrials) {
        return StudyConfig.parse(Json.parse("test config", """
                {"comment": "Branin and an integer",
                 "objectives": [{"name": "regret", "direction": "minimize"}],
                 "params": [{"name": "x", "low": -5, "high": 10, "comment": "first Branin coordinate"},
                            {"name": "y", "low": 0, "high": 15},
                            {"name": "n", "low": 1, "high": 9, "int": true}],
                 "parallelTrials": %d}
                """.formatted(parallelTrials)));
    }

    /** Branin's regret + 0.01 |n - 3|, after a pause of 0-4 ms that varies with the trial so finishing order shuffles. */
    private static Evaluation branin(TrialParams p) throws InterruptedException {
        Thread.sleep((p.number() * 7) % 5);
        double x = p.get("x"), y = p.get("y"), b = 5.1 / (4 * Math.PI * Math.PI), c = 5 / Math.PI, t = 1 / (8 * Math.PI);
        double f = Math.pow(y - b * x * x + c * x - 6, 2) + 10 * (1 - t) * Math.cos(x) + 10 - 0.397887;
        return Evaluation.of(f + 0.01 * Math.abs(p.integer("n") - 3)).with("x2", x * x);
    }

    private static ObjectNode provenance(String how) {
        return Json.mapper().createObjectNode().put("command", how);
    }

    private static void assertSameTrials(Study expected, Study actual) {
        List<TrialRecord> a = expected.trials(), b = actual.trials();
        assertEquals(a.size(), b.size(), "trial count");
        for (int i = 0; i < a.size(); i++) {
            assertEquals(a.get(i).number(), b.get(i).number());
            assertArrayEquals(a.get(i).params(), b.get(i).params(), 0.0, "trial " + i + " params");
            assertArrayEquals(a.get(i).values(), b.get(i).values(), 0.0, "trial " + i + " values");
            assertEquals(a.get(i).error(), b.get(i).error(), "trial " + i + " error");
        }
    }

    @Test
    void aStudyWritesItsTrialsBestTrialAndHistory(@TempDir Path tmp) throws Exception {
        ByteArrayOutputStream lines = new ByteArrayOutputStream();
        Study study = Study.openOrCreate(tmp, config(2), SEED, provenance("test"));
        study.run(StudyTest::branin, 30, 2, new PrintStream(lines, true, StandardCharsets.UTF_8));

        try (var files = Files.list(tmp.resolve(Study.TRIALS_DIR))) {
            assertEquals(30, files.filter(f -> f.toString().endsWith(".json")).count(), "one file per trial");
        }
        // read back from disk, the study is bit-identical to the one in memory
        Study reread = Study.open(tmp);
        assertSameTrials(study, reread);
        TrialRecord best = reread.best().orElseThrow();
        double min = reread.trials().stream().mapToDouble(t -> t.values()[0]).min().orElseThrow();
        assertEquals(min, best.values()[0], 0.0, "best is the smallest value");
        assertEquals(best.number(), Json.load(tmp.resolve(Study.BEST_FILE)).get("best").integer("number"));
        assertEquals(best.params()[0] * best.params()[0], best.info().get("x2"), 0.0, "the objective's info is kept");
        // study.json: config, seed, sampler, this run's provenance
        Json studyJson = Json.load(tmp.resolve(Study.STUDY_FILE));
        assertEquals(SEED, studyJson.longValue("seed"));
        assertEquals(config(2).toJson(), studyJson.get("config").node());
        assertEquals("test", studyJson.array("runs").get(0).get("provenance").string("command"));
        byte[] png = Files.readAllBytes(tmp.resolve("history.png"));
        assertTrue(png.length > 1000 && png[1] == 'P' && png[2] == 'N' && png[3] == 'G', "history.png is a PNG");
        // a progress line per trial, with an ETA
        List<String> progress = lines.toString(StandardCharsets.UTF_8).lines().filter(l -> l.startsWith("trial ")).toList();
        assertEquals(30, progress.size(), "progress lines");
        assertTrue(progress.stream().allMatch(l -> l.contains("ETA ") && l.contains("best ")), progress.get(0));
    }

    @Test
    void resultsDoNotDependOnTheNumberOfWorkers(@TempDir Path tmp) throws Exception {
        Study[] studies = new Study[3];
        for (int workers = 1; workers <= 3; workers++) {
            AtomicInteger inFlight = new AtomicInteger(), maxInFlight = new AtomicInteger();
            int w = workers;
            studies[workers - 1] = Study.openOrCreate(tmp.resolve("w" + workers), config(3), SEED, provenance("workers " + workers));
            studies[workers - 1].run(p -> {
                maxInFlight.accumulateAndGet(inFlight.incrementAndGet(), Math::max);
                try {
                    // the first trials wait (10 s at most) until as many run at once as the study has workers: what is
                    // measured is whether it starts that many together, not whether a trial of a few ms outlasts the
                    // study's writing of the last one's file (forced to disk)
                    long deadline = System.nanoTime() + 10_000_000_000L;
                    while (p.number() < w && maxInFlight.get() < w && System.nanoTime() < deadline) {
                        Thread.sleep(1);
                    }
                    return branin(p);
                } finally {
                    inFlight.decrementAndGet();
                }
            }, 25, workers, null);
            assertEquals(workers, maxInFlight.get(), "trials running at once with " + workers + " workers (parallelTrials 3)");
        }
        assertSameTrials(studies[0], studies[1]);
        assertSameTrials(studies[0], studies[2]);
    }

    @Test
    void aStoppedStudyResumesToTheTrialsOfAnUninterruptedOne(@TempDir Path tmp) throws Exception {
        Study reference = Study.openOrCreate(tmp.resolve("whole"), config(2), SEED, provenance("whole"));
        reference.run(StudyTest::branin, 30, 2, null);

        // the same study, interrupted when its 14th trial starts (trials running then are lost)
        Path dir = tmp.resolve("stopped");
        Study first = Study.openOrCreate(dir, config(2), SEED, provenance("first"));
        AtomicInteger started = new AtomicInteger();
        Thread runner = Thread.currentThread();
        assertThrows(InterruptedException.class, () -> first.run(p -> {
            if (started.incrementAndGet() == 14) {
                runner.interrupt();
            }
            return branin(p);
        }, 30, 2, null));
        int finishedBefore = Study.open(dir).trials().size();
        assertTrue(finishedBefore >= 10 && finishedBefore < 14, finishedBefore + " trials finished before the stop");
        // a kill may leave a temporary file behind: it is ignored
        Files.writeString(dir.resolve(Study.TRIALS_DIR).resolve("trial-0013.json.tmp"), "{\"number\": 13, \"sta");

        Study resumed = Study.openOrCreate(dir, config(2), SEED, provenance("resume"));
        assertEquals(finishedBefore, resumed.trials().size(), "finished trials read back");
        resumed.run(StudyTest::branin, 30, 1, null);
        assertSameTrials(reference, Study.open(dir));
        assertEquals(2, Json.load(dir.resolve(Study.STUDY_FILE)).array("runs").size(), "both runs recorded");
    }

    @Test
    void aResumeWithAnotherSeedOrConfigIsRefusedNamingTheField(@TempDir Path tmp) throws Exception {
        Study.openOrCreate(tmp, config(2), SEED, provenance("a")).run(StudyTest::branin, 3, 1, null);
        ConfigException seed = assertThrows(ConfigException.class, () -> Study.openOrCreate(tmp, config(2), SEED + 1, provenance("b")));
        assertTrue(seed.getMessage().contains("seed: the study was created with seed 5, not 6"), seed.getMessage());
        ConfigException cfg = assertThrows(ConfigException.class, () -> Study.openOrCreate(tmp, config(1), SEED, provenance("c")));
        assertTrue(cfg.getMessage().contains("config.parallelTrials: 2 in the study, 1 given"), cfg.getMessage());
    }

    @Test
    void failedTrialsAreRecordedAndLeftOutOfTheSampler(@TempDir Path tmp) throws Exception {
        // trials 3 and 7 fail (an exception, a NaN): recorded with their error, not in the best
        Study study = Study.openOrCreate(tmp, config(1), SEED, provenance("fail"));
        study.run(p -> {
            if (p.number() == 3) {
                throw new IllegalStateException("simulation diverged");
            }
            return p.number() == 7 ? Evaluation.of(Double.NaN) : branin(p);
        }, 15, 2, null);
        List<TrialRecord> trials = Study.open(tmp).trials();
        assertEquals(15, trials.size());
        assertEquals("java.lang.IllegalStateException: simulation diverged", trials.get(3).error());
        assertEquals("regret is NaN", trials.get(7).error());
        assertEquals(13, trials.stream().filter(TrialRecord::isComplete).count());
    }

    @Test
    void badConfigsNameTheFieldAndTheValue() {
        String base = """
                {"objectives": [{"name": "f", "direction": "minimize"}], "parallelTrials": 1,
                 "params": [%s]}""";
        assertConfigError(base.formatted("{\"name\": \"x\", \"low\": 1, \"high\": 1}"), "params[0]: param x: low must be < high");
        assertConfigError(base.formatted("{\"name\": \"x\", \"low\": 0, \"high\": 1, \"log\": true}"), "params[0]: param x: a log-scale parameter needs low > 0, got 0.0");
        assertConfigError(base.formatted("{\"name\": \"x\", \"low\": 0, \"high\": 1, \"lgo\": true}"), "params[0].lgo: unknown field");
        assertConfigError(base.formatted("{\"name\": \"n\", \"low\": 0.5, \"high\": 3, \"int\": true}"), "an integer's low and high must be whole numbers");
        assertConfigError(base.replace("minimize", "minimise").formatted("{\"name\": \"x\", \"low\": 0, \"high\": 1}"),
                "objectives[0].direction: must be one of minimize, maximize, got \"minimise\"");
        assertConfigError(base.replace("\"parallelTrials\": 1", "\"parallelTrials\": 0").formatted("{\"name\": \"x\", \"low\": 0, \"high\": 1}"),
                "parallelTrials: must be in [1, 1024], got 0");
    }

    private static void assertConfigError(String json, String expected) {
        ConfigException e = assertThrows(ConfigException.class, () -> StudyConfig.parse(Json.parse("c.json", json)));
        assertTrue(e.getMessage().startsWith("c.json: ") && e.getMessage().contains(expected), e.getMessage());
    }
}
