package handsim.spec;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.config.ConfigException;
import handsim.config.ConfigSet;
import handsim.config.Home;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A run's configs parsed from a home of the test's own: the planner settings per object. */
@Tag("fast")
class RunConfigsTest {

    @Test
    void plannerSettingsForAnObjectThatDoesNotExistAreRefusedByName(@TempDir Path home) throws Exception {
        Files.createDirectories(home.resolve("models"));
        Files.createDirectories(home.resolve("configs/objects"));
        Files.copy(Home.resolve("configs/objects/club.json"), home.resolve("configs/objects/club.json"));
        String planner = "{\"rounds\": [{\"candidates\": 24, \"spread\": 0.1}], \"goodAlignment\": 0.9, \"lookahead\": 0, "
                + "\"objects\": {%s: {\"rounds\": [{\"candidates\": 40, \"spread\": 0.05}], \"lookahead\": 3}}}";
        String before = System.getProperty("handsim.home");
        System.setProperty("handsim.home", home.toString());
        try {
            Files.writeString(home.resolve("configs/planner.json"), planner.formatted("\"club\""));
            RunConfigs configs = new RunConfigs(ConfigSet.fromFiles());
            assertEquals(3, configs.planner("club").lookahead());
            assertEquals(0, configs.planner("can").lookahead(), "an object without an entry keeps the file's settings");

            Files.writeString(home.resolve("configs/planner.json"), planner.formatted("\"clb\""));
            var e = assertThrows(ConfigException.class, () -> new RunConfigs(ConfigSet.fromFiles()).planner("club"));
            assertTrue(e.getMessage().contains("objects.clb") && e.getMessage().contains("no such object"), e.getMessage());
        } finally {
            if (before == null) {
                System.clearProperty("handsim.home");
            } else {
                System.setProperty("handsim.home", before);
            }
        }
    }
}
