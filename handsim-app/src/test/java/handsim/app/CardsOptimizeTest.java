package handsim.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.cards.study.Study;
import handsim.cards.study.TrialRecord;
import handsim.config.Json;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code handsim cards optimize --sleight snap} end to end on coarse fingertips and a 0.1 s
 * trial: the study folder, the best (chosen) trial replayed with its frames and played by the viewer, a
 * resume after an interruption that gives the trials of an uninterrupted study run on another
 * number of workers, and bad input refused with status 2.
 */
@Tag("slow")
class CardsOptimizeTest {

    /** A search space that fits the 0.1 s trial; two start-up trials, so the third comes from TPE. */
    private static final String CONFIG = """
            {"objectives": [{"name": "objective", "direction": "minimize", "tolerance": 5}],
             "params": [{"name": "t0", "low": 0.0, "high": 0.02}, {"name": "t1", "low": 0.02, "high": 0.04},
                        {"name": "vp", "low": 0.001, "high": 0.004}, {"name": "t2", "low": 0.04, "high": 0.05},
                        {"name": "t3", "low": 0.05, "high": 0.1}, {"name": "vs", "low": 0.005, "high": 0.04}],
             "parallelTrials": 2,
             "sampler": {"nStartupTrials": 2}}
            """;

    private static List<String> args(Path config, Path out, int trials, int workers, String... more) {
        List<String> a = new ArrayList<>(List.of("cards", "optimize", "--sleight", "snap", "--trials", String.valueOf(trials), "--seed", "7",
                "--workers", String.valueOf(workers), "--config", config.toString(), "--out", out.toString(), "--mesh", "coarse",
                "--set", "snap.trial.duration=0.1", "--set", "snap.hold.warmup=0.1", "--set", "snap.fingertip.softLayers=1",
                "--set", "snap.params={\"t0\": 0, \"t1\": 0.02, \"vp\": 0.002, \"t2\": 0.04, \"t3\": 0.08, \"vs\": 0.01}"));
        a.addAll(List.of(more));
        return a;
    }

    private static int run(List<String> args) {
        return Main.run(args.toArray(String[]::new));
    }

    @Test
    void aTinyStudyRunsEndToEndAndResumesAfterAnInterruptionToTheSameTrials(@TempDir Path tmp) throws Exception {
        Path config = tmp.resolve("study.json");
        Files.writeString(config, CONFIG);
        Path whole = tmp.resolve("whole");
        assertEquals(0, run(args(config, whole, 3, 2, "--width", "160", "--height", "120")));

        Study study = Study.open(whole);
        assertEquals(3, study.trials().size());
        for (TrialRecord t : study.trials()) {
            assertTrue(t.isComplete(), "trial " + t.number() + ": " + t.error());
            assertTrue(t.info().get("minGap") > 0, "no interpenetration in trial " + t.number());
        }
        // best.json names the trial of least objective, which is also the chosen one (a single objective); chosen/ holds
        // its replay, which reproduces it
        TrialRecord best = study.best().orElseThrow();
        double least = study.trials().stream().mapToDouble(t -> t.values()[0]).min().orElseThrow();
        assertEquals(least, best.values()[0], 0.0);
        assertEquals(best.number(), Json.load(whole.resolve(Study.BEST_FILE)).get("best").integer("number"));
        assertEquals(best.number(), Json.load(whole.resolve(Study.BEST_FILE)).get("chosen").integer("number"));
        Json replay = Json.load(whole.resolve("chosen/result.json"));
        assertEquals(best.number(), replay.integer("trial"));
        assertEquals(best.values()[0], replay.get("objectives").number("objective"), 0.0, "the replay gives the trial's objective bit for bit");
        assertTrue(replay.bool("reproducesTrial", false));
        for (String f : List.of("history.png", "chosen/strip.png", "chosen/frames/00000.png", "chosen/trajectory.json")) {
            assertTrue(Files.size(whole.resolve(f)) > 100, f);
        }
        // study.json records what the objective is (mesh and overridden snap.json)
        Json recorded = Json.load(whole.resolve(Study.STUDY_FILE)).get("objective");
        assertEquals("coarse", recorded.string("mesh"));
        assertEquals(0.1, recorded.get("snap").get("trial").number("duration"), 0.0);

        // cards robust replays the chosen trial 13 times (each of 6 parameters -1 % and +1 % of its range, and on the
        // reduced fingertips) and counts those within the 5 degree tolerance
        assertEquals(0, Main.run("cards", "robust", "--study", whole.toString(), "--workers", "2"));
        Json robust = Json.load(whole.resolve("robust.json"));
        assertEquals(13, robust.integer("replays"));
        int met = 0;
        for (Json r : robust.array("results")) {
            boolean within = r.has("values") && r.get("values").node().get(0).asDouble() <= 5;
            assertEquals(within, r.bool("meetsTolerances", !within), r.string("label"));
            met += within ? 1 : 0;
        }
        assertEquals(met, robust.integer("meetTolerances"));
        assertEquals("reduced", robust.array("results").get(12).string("mesh"));

        // the viewer plays the study's best trial; a folder without one is refused
        assertEquals(0, Main.run("view", "--scene", "snap", "--study", whole.toString(), "--benchmark-frames", "2"));
        assertEquals(2, Main.run("view", "--scene", "snap", "--study", tmp.toString(), "--benchmark-frames", "2"));

        // a resume with another seed or another scene is refused
        List<String> otherSeed = args(config, whole, 3, 2);
        otherSeed.set(otherSeed.indexOf("7"), "8");
        assertEquals(2, run(otherSeed));
        assertEquals(2, run(args(config, whole, 3, 2, "--set", "snap.trial.alphaTarget=3")));

        // the same study on one worker, killed after two trials while trial 1 was running: trial 1's
        // file never got written, a fragment of its temporary file may remain
        Path stopped = tmp.resolve("stopped");
        assertEquals(0, run(args(config, stopped, 2, 1, "--no-frames")));
        Path trials = stopped.resolve(Study.TRIALS_DIR);
        Files.delete(trials.resolve("trial-0001.json"));
        Files.writeString(trials.resolve("trial-0001.json.tmp"), "{\"number\": 1, \"sta");
        // the same command continues it
        assertEquals(0, run(args(config, stopped, 3, 1, "--no-frames")));
        List<TrialRecord> a = study.trials();
        List<TrialRecord> b = Study.open(stopped).trials();
        assertEquals(a.size(), b.size());
        for (int i = 0; i < a.size(); i++) {
            assertArrayEquals(a.get(i).params(), b.get(i).params(), 0.0, "trial " + i + " params");
            assertArrayEquals(a.get(i).values(), b.get(i).values(), 0.0, "trial " + i + " objective");
        }
    }

    @Test
    void badInputIsRefusedWithStatusTwoAndNothingWritten(@TempDir Path tmp) throws Exception {
        Path config = tmp.resolve("study.json");
        Files.writeString(config, CONFIG);
        Path out = tmp.resolve("out");
        assertEquals(2, run(List.of("cards", "optimize", "--sleight", "lift", "--trials", "3", "--seed", "1", "--out", out.toString())));
        assertEquals(2, run(args(config, out, 0, 1)), "--trials 0");
        assertEquals(2, run(args(config, out, 3, 0)), "--workers 0");
        assertEquals(2, run(args(config, out, 3, 1, "--set", "snap.trial.duration=-1")), "a bad snap.json value");
        assertEquals(2, run(args(config, out, 3, 1, "--set", "snap.nonesuch.field=1")), "a --set path that does not exist");
        assertEquals(2, run(args(config, out, 3, 1, "--set", "trial.duration=0.2")), "a --set key without its file");
        // a search space beyond the trial's 0.1 s, and one without vs
        Path late = tmp.resolve("late.json");
        Files.writeString(late, CONFIG.replace("\"high\": 0.1}", "\"high\": 0.2}"));
        assertEquals(2, run(args(late, out, 3, 1)));
        Path noVs = tmp.resolve("novs.json");
        Files.writeString(noVs, CONFIG.replace(", {\"name\": \"vs\", \"low\": 0.005, \"high\": 0.04}", ""));
        assertEquals(2, run(args(noVs, out, 3, 1)));
        assertEquals(2, run(args(tmp.resolve("missing.json"), out, 3, 1)));
        assertFalse(Files.exists(out), "nothing written for refused input");
    }
}
