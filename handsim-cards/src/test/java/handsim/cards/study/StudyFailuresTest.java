package handsim.cards.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.ConfigException;
import handsim.config.Json;
import handsim.report.Stop;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Nothing a trial does stops a study: a trial past its budget or out of memory is failed with its
 * reason and the study goes on; a hand-edited trial file outside the search space is refused on
 * resume; a stop request ends the study with the finished trials recorded.
 */
@Tag("fast")
class StudyFailuresTest {

    private static final StudyConfig CONFIG = StudyConfig.parse(Json.parse("test config", """
            {"objectives": [{"name": "f", "direction": "minimize"}],
             "params": [{"name": "x", "low": -1, "high": 1}], "parallelTrials": 1}
            """));

    private static ObjectNode provenance() {
        return Json.mapper().createObjectNode().put("command", "test");
    }

    @Test
    void aTrialPastItsBudgetOrOutOfMemoryFailsWithItsReasonAndTheStudyGoesOn(@TempDir Path tmp) throws Exception {
        Study study = Study.openOrCreate(tmp, CONFIG, 3, provenance());
        study.run(p -> {
            if (p.number() == 1) {
                throw new Objective.TrialFailed("past its budget: more than 40 Newton iterations by step 2", null);
            }
            if (p.number() == 2) {
                throw new OutOfMemoryError("Java heap space");
            }
            return Evaluation.of(p.get("x") * p.get("x"));
        }, 5, 1, null);
        List<TrialRecord> trials = Study.open(tmp).trials();
        assertEquals(5, trials.size(), "every trial finished");
        assertEquals("past its budget: more than 40 Newton iterations by step 2", trials.get(1).error(), "the reason, as said");
        assertEquals("out of memory (Java heap space)", trials.get(2).error());
        assertEquals(3, trials.stream().filter(TrialRecord::isComplete).count());
        assertTrue(study.best().orElseThrow().isComplete());
    }

    @Test
    void aTrialFileEditedOutsideTheSearchSpaceIsRefusedOnResume(@TempDir Path tmp) throws Exception {
        Study.openOrCreate(tmp, CONFIG, 3, provenance()).run(p -> Evaluation.of(p.get("x")), 2, 1, null);
        Path trial = tmp.resolve(Study.TRIALS_DIR).resolve("trial-0001.json");
        Files.writeString(trial, Files.readString(trial).replaceFirst("\"x\" : [-0-9.eE]+", "\"x\" : -1000000.0"));
        ConfigException e = assertThrows(ConfigException.class, () -> Study.openOrCreate(tmp, CONFIG, 3, provenance()));
        assertEquals(trial + ": params.x: -1000000 is outside the study's search space [-1, 1] (a trial file edited by hand, or one "
                + "of another study?)", e.getMessage());
    }

    @Test
    void aStopRequestEndsTheStudyWithTheFinishedTrialsRecorded(@TempDir Path tmp) throws Exception {
        Study study = Study.openOrCreate(tmp, CONFIG, 3, provenance());
        try {
            Stop.Stopped stopped = assertThrows(Stop.Stopped.class, () -> study.run(p -> {
                if (p.number() == 2) {
                    Stop.request("SIGTERM"); // while trial 2 runs: it is abandoned, 0 and 1 are kept
                    Thread.sleep(2000);
                }
                return Evaluation.of(p.get("x"));
            }, 6, 1, null));
            assertTrue(stopped.getMessage().startsWith("stopped by SIGTERM: 2 trials finished, kept in "), stopped.getMessage());
        } finally {
            Stop.reset();
        }
        assertEquals(2, Study.open(tmp).trials().size());
        assertEquals(2, Json.load(tmp.resolve(Study.BEST_FILE)).integer("finished"), "best.json records what finished");
    }
}
