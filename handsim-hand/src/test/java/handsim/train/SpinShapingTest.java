package handsim.train;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.config.Json;
import handsim.task.LoopRecord;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The training-only release-spin term of flip runs, and how a run config gives it. */
@Tag("fast")
class SpinShapingTest {

    private static LoopRecord leavingAt(double spin) {
        return new LoopRecord(1, true, 1.3, null, Double.NaN, null, false, Double.NaN, Math.PI, spin, 0, Double.NaN,
                null, Double.NaN, 0, 0, 0, 1);
    }

    @Test
    void theTermIsItsWeightAtTheTargetAndFallsToOneOverEAWidthAway() {
        SpinShaping s = new SpinShaping(0.5, 8, 2);
        // the Gaussian of SpinShaping's doc, exact up to rounding
        assertEquals(0.5, s.bonus(leavingAt(8)), 1e-12);
        assertEquals(0.5 / Math.E, s.bonus(leavingAt(10)), 1e-12);
        assertEquals(0.5 / Math.E, s.bonus(leavingAt(6)), 1e-12);
        assertTrue(s.bonus(leavingAt(1)) < 1e-4, "a throw that hardly spins earns nothing");
        assertEquals(0, s.bonus(leavingAt(Double.NaN)), "loop 0 and objects without a long axis have no release spin");
        assertEquals(0, SpinShaping.NONE.bonus(leavingAt(8)), "none is the paper's reward");
    }

    @Test
    void aRunGivesItInItsRunSectionAndARunWithoutItHasNone() {
        Path file = Home.resolve("configs/train/flip.json");
        var node = Json.load(file).node();
        TrainConfig plain = TrainConfig.parse(Json.of("plain", node));
        assertEquals(SpinShaping.NONE, plain.run().spinShaping());
        assertFalse(plain.toJson().get("run").has("spinShaping"), "a run without the term saves no such field");
        TrainConfig shaped = TrainConfig.parse(Json.of("shaped", Json.withOverrides(file.toString(), node,
                Map.of("run.spinShaping", "{\"weight\": 0.5, \"target\": 8, \"width\": 2}"))));
        assertEquals(new SpinShaping(0.5, 8, 2), shaped.run().spinShaping());
        assertEquals(shaped, TrainConfig.parse(Json.of("saved", shaped.toJson())), "the run folder's config gives it back");
        ConfigException e = assertThrows(ConfigException.class, () -> TrainConfig.parse(Json.of("bad", Json.withOverrides(
                file.toString(), node, Map.of("run.spinShaping", "{\"weight\": 0.5, \"target\": 8, \"width\": 0}")))));
        assertTrue(e.getMessage().contains("width"), e.getMessage());
    }
}
