package handsim.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import handsim.rollout.RolloutTask;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The journal of finished episodes: kept across runs of the same signature, refused for another, robust to a cut line. */
@Tag("fast")
class EpisodeJournalTest {

    private static ObjectNode signature(long seed) {
        ObjectNode s = JsonNodeFactory.instance.objectNode().put("task", "flip").put("seed", seed);
        s.putObject("files").put("configs/sim.json", "abc");
        return s;
    }

    @Test
    void finishedEpisodesAreReadBackByTheSameRunAndACutLineIsDropped(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("r.json.episodes.jsonl");
        EpisodeJournal first = EpisodeJournal.open(file, signature(1), "c1");
        assertEquals(0, first.finished());
        first.append(2, JsonNodeFactory.instance.objectNode().put("loops", 7).put("x", 0.1 + 0.2));
        first.append(0, JsonNodeFactory.instance.objectNode().put("loops", 3));
        // a kill in the middle of the next append leaves half a line
        Files.writeString(file, "{\"index\":1,\"resu", StandardCharsets.UTF_8, StandardOpenOption.APPEND);

        EpisodeJournal again = EpisodeJournal.open(file, signature(1), "c1");
        assertEquals(2, again.finished());
        assertEquals(1, again.droppedLines());
        assertEquals(7, again.result(2).orElseThrow().get("loops").asInt());
        assertEquals(0.1 + 0.2, again.result(2).orElseThrow().get("x").asDouble(), 0, "a double reads back to the same bits");
        assertFalse(again.result(1).isPresent(), "the episode cut short runs again");
        // the run resumed by other code (commit c2) reads episodes 0 and 2 back and runs 1, whose
        // line starts on a line of its own after the cut one
        EpisodeJournal resumed = EpisodeJournal.open(file, signature(1), "c2");
        assertEquals(List.of(3, 5, 7), runEpisodes(resumed, 3, 5), "0 and 2 read back, 1 run");
        assertEquals(2, resumed.resumed());
        assertEquals(Map.of("c1", 2, "c2", 1), resumed.episodesByCommit(), "two episodes ran at c1, one at c2");
        EpisodeJournal third = EpisodeJournal.open(file, signature(1), "c3");
        assertEquals(3, third.finished());
        assertEquals(5, third.result(1).orElseThrow().get("loops").asInt());
        // a run of fewer episodes counts only those it used; a line without a commit is unrecorded
        Files.writeString(file, "{\"index\":4,\"result\":{\"loops\":1}}\n", StandardCharsets.UTF_8, StandardOpenOption.APPEND);
        EpisodeJournal two = EpisodeJournal.open(file, signature(1), "c3");
        assertEquals(List.of(3, 5), runEpisodes(two, 2, 0));
        assertEquals(Map.of("c1", 1, "c2", 1), two.episodesByCommit(), "episodes 2 and 4 are journaled but not this run's");
        assertEquals(2, two.resumed());
        EpisodeJournal five = EpisodeJournal.open(file, signature(1), "c3");
        assertEquals(List.of(3, 5, 7, 9, 1), runEpisodes(five, 5, 9));
        assertEquals(Map.of("c1", 2, "c2", 1, "c3", 1, EpisodeJournal.UNRECORDED, 1), five.episodesByCommit());
        third.delete();
        assertFalse(Files.exists(file));
    }

    /**
     * Episodes 0 to n-1 through the journal: those it holds read back (their "loops"), the others
     * run, giving {@code ran} and journaled.
     */
    private static List<Integer> runEpisodes(EpisodeJournal journal, int n, int ran) {
        RolloutTask.Rollout<JsonNode> rollout = journal.<Void, JsonNode>resumable(
                worker -> i -> JsonNodeFactory.instance.objectNode().put("loops", ran), r -> r, r -> r).prepare(null);
        List<Integer> loops = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            loops.add(rollout.run(i).get("loops").asInt());
        }
        return loops;
    }

    @Test
    void anotherRunsJournalIsRefusedNamingWhatDiffers(@TempDir Path dir) {
        Path file = dir.resolve("r.json.episodes.jsonl");
        EpisodeJournal.open(file, signature(1), "c1").append(0, JsonNodeFactory.instance.objectNode());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> EpisodeJournal.open(file, signature(2), "c1"));
        assertTrue(e.getMessage().contains("seed was 1, is 2"), e.getMessage());
        ObjectNode changedConfig = signature(1);
        ((ObjectNode) changedConfig.get("files")).put("configs/sim.json", "abd");
        e = assertThrows(IllegalArgumentException.class, () -> EpisodeJournal.open(file, changedConfig, "c1"));
        assertTrue(e.getMessage().contains("files.configs/sim.json"), e.getMessage());
    }
}
