package handsim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code handsim cards snap}: bad input is refused with exit status 2 and nothing written. */
@Tag("fast")
class CardsCommandTest {

    @Test
    void inconsistentParamsAreRefusedWithStatusTwoAndNothingWritten(@TempDir Path dir) throws Exception {
        Path params = dir.resolve("params.json");
        Files.writeString(params, "{\"t0\": 0.1, \"t1\": 0.05, \"vp\": 0.003, \"t2\": 0.15, \"t3\": 0.35, \"vs\": 0.01}");
        Path out = dir.resolve("out");
        assertEquals(2, Main.run("cards", "snap", "--mesh", "coarse", "--params", params.toString(), "--out", out.toString()));
        assertFalse(Files.exists(out), "no output folder for refused input");
        assertEquals(2, Main.run("cards", "snap", "--mesh", "nonesuch"));
    }
}
