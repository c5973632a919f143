package handsim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code --master} on this module's classpath, which holds no cluster engine (handsim-spark is
 * never on the default path): each command that takes it refuses in one line naming what to
 * build, with status 2, before it writes anything; options that a cluster makes meaningless are
 * refused by name.
 */
@Tag("fast")
class ClusterOptionsTest {

    @Test
    void withoutTheClusterModuleAMasterIsRefusedBeforeAnythingIsWritten(@TempDir Path tmp) throws Exception {
        Path study = tmp.resolve("study");
        CliRun.of("cards", "optimize", "--sleight", "snap", "--trials", "2", "--seed", "1", "--no-frames", "--out", study.toString(),
                "--master", "local[2]").assertRefused(2, "--master local[2]", "no cluster engine", "handsim-spark");
        assertFalse(Files.exists(study), "no study folder");

        Path json = tmp.resolve("box.json");
        CliRun.of("evaluate", "--task", "box", "--tests", "1", "--json", json.toString(), "--master", "spark://127.0.0.1:7077")
                .assertRefused(2, "--master spark://127.0.0.1:7077", "handsim-spark");
        assertFalse(Files.exists(json) || Files.exists(tmp.resolve("box.json.episodes.jsonl")), "no results, no journal");

        Path runs = tmp.resolve("runs");
        CliRun.of("warmstart", "--config", "configs/train/flip-warmstart.json", "--runs", runs.toString(), "--master", "local[2]")
                .assertRefused(2, "--master", "handsim-spark");
        CliRun.of("dagger", "--config", "configs/train/flip-dagger.json", "--runs", runs.toString(), "--master", "local[2]")
                .assertRefused(2, "--master", "handsim-spark");
        assertEquals(Map.of(), CliRun.contents(runs), "no run folder");
    }

    @Test
    void optionsOfThisMachinesThreadsGoWithoutAMaster(@TempDir Path tmp) {
        CliRun.of("evaluate", "--task", "box", "--tests", "1", "--workers", "2", "--master", "local[2]")
                .assertRefused(2, "--workers goes without --master");
        CliRun.of("cards", "optimize", "--sleight", "snap", "--trials", "2", "--seed", "1", "--workers", "2", "--no-frames", "--out",
                tmp.resolve("s").toString(), "--master", "local[2]").assertRefused(2, "--workers goes without --master");
        CliRun.of("evaluate", "--task", "box", "--tests", "1", "--master", " ").assertRefused(2, "--master must be a URL");
    }
}
