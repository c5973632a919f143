package handsim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** What a result says of where it came from. */
@Tag("fast")
class ProvenanceTest {

    @Test
    void aRunRecordsTheCommitItBeganWithAndItsCommandLine() {
        // evaluate reads the commit before it runs and hands it here: a tree committed during a
        // long run must not name a commit whose code did not make the result
        var p = Provenance.of(List.of("evaluate", "--task", "flip"), "0123abc+changes");
        assertEquals("0123abc+changes", p.get("commit").asText());
        assertEquals("scripts/handsim evaluate --task flip", p.get("command").asText());
    }
}
