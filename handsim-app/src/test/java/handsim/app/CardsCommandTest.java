package handsim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code handsim cards snap|lift|robust}, {@code view} and {@code export} of card trials: bad input is refused with exit status 2 and nothing written. */
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

    @Test
    void badLiftInputIsRefusedWithStatusTwoAndNothingWritten(@TempDir Path dir) throws Exception {
        // the lift must end 0.2 s before the 0.65 s trial does: t3 = 0.5 is refused by name
        Path params = dir.resolve("params.json");
        Files.writeString(params, "{\"hStart\": 0, \"t0\": 0, \"t1\": 0.1, \"vp\": 0.004, \"t2\": 0.15, \"t3\": 0.5, \"vs\": 0.02}");
        Path out = dir.resolve("out");
        assertEquals(2, Main.run("cards", "lift", "--mesh", "coarse", "--params", params.toString(), "--out", out.toString()));
        Files.writeString(params, "{\"t0\": 0, \"t1\": 0.1, \"vp\": 0.004, \"t2\": 0.15, \"t3\": 0.35, \"vs\": 0.02}");
        assertEquals(2, Main.run("cards", "lift", "--mesh", "coarse", "--params", params.toString(), "--out", out.toString()), "no hStart");
        assertEquals(2, Main.run("cards", "lift", "--set", "double-lift.stack.freeCards=60", "--out", out.toString()), "more free cards than the stack has");
        assertEquals(2, Main.run("cards", "lift", "--set", "lift.trial.hTarget=0.004"), "an override of no file");
        assertFalse(Files.exists(out), "no output folder for refused input");
        assertEquals(2, Main.run("cards", "robust", "--study", dir.toString()), "a folder that holds no study");
        assertEquals(2, Main.run("export", "--scene", "double-lift", "--out", dir.resolve("x.glb").toString()), "no trajectory");
        assertEquals(2, Main.run("export", "--scene", "nonesuch", "--trajectory", params.toString(), "--out", dir.resolve("x.glb").toString()));
        assertEquals(2, Main.run("view", "--scene", "double-lift", "--trajectory", dir.resolve("missing.json").toString()));
        assertFalse(Files.exists(dir.resolve("x.glb")));
    }
}
