package handsim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import handsim.config.Home;
import java.nio.file.Path;

import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

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

    @Test
    void aRunWithItsHomeOutsideTheProjectRecordsTheProjectsCommit(@TempDir Path home) {
        // HANDSIM_HOME puts the configs and runs in a folder that is no git repository; the
        // launcher names the project whose code runs (-Dhandsim.code), and that is the commit
        Path project = Home.root();
        String expected = Provenance.gitCommit(project);
        assumeTrue(!expected.equals("unknown"), "the project is not a git checkout here");
        assertEquals("unknown", Provenance.gitCommit(home), "a folder outside any repository has no commit");
        String savedHome = System.getProperty("handsim.home"), savedCode = System.getProperty("handsim.code");
        try {
            System.setProperty("handsim.home", home.toString());
            System.setProperty("handsim.code", project.toString());
            assertEquals(expected, Provenance.gitCommit());
            assertTrue(expected.matches("[0-9a-f]{40}(\\+changes)?"), expected);
        } finally {
            restore("handsim.home", savedHome);
            restore("handsim.code", savedCode);
        }
    }

    private static void restore(String key, String value) {
        if (value == null) {
            System.clearProperty(key);
        } else {
            System.setProperty(key, value);
        }
    }
}
