package handsim.cards.sleight;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import handsim.cards.study.StudyConfig;
import handsim.config.ConfigException;
import handsim.config.Json;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Physical ranges, checked before anything is simulated: bone speeds (a flick of a finger is
 * 2 m/s), gravity (ten times the Earth's), mesh sizes, and the search space's bounds.
 */
@Tag("fast")
class SnapBoundsTest {

    @Test
    void aSlideOfAMillionMetresASecondIsRefusedByName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new SnapParams(0, 0.1, 0.003, 0.15, 0.35, 1e6).validate(0.6, "p.json"));
        assertEquals("p.json: vs must be a speed in [0, 2] m/s, got 1000000", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new SnapParams(0, 0.1, 2.5, 0.15, 0.35, 0.01).validate(0.6, null));
    }

    @Test
    void configsBeyondPhysicalRangesAreRefusedNamingTheField() {
        ConfigException gravity = assertThrows(ConfigException.class,
                () -> SnapTrial.fromConfigs(Path.of(""), "coarse", null, Map.of("solver.gravity", "[0, 0, -1e9]")));
        assertEquals("configs/cards/solver.json: gravity: its magnitude must be at most 100 m/s² (ten times the Earth's), got 1E+9",
                gravity.getMessage());
        ConfigException cells = assertThrows(ConfigException.class,
                () -> SnapTrial.fromConfigs(Path.of(""), "coarse", null, Map.of("snap.card.cells", "[100000, 6]")));
        assertEquals("configs/cards/snap.json: card.cells: need 2 to 200 a side, got [100000, 6]", cells.getMessage());
        ConfigException tip = assertThrows(ConfigException.class,
                () -> SnapTrial.fromConfigs(Path.of(""), "coarse", null, Map.of("snap.fingertip.semiAxes", "[1, 0.0075, 0.006]")));
        assertEquals("configs/cards/snap.json: fingertip.semiAxes: each must be in [0.001, 0.05] m, got [1.0, 0.0075, 0.006]",
                tip.getMessage());
        assertThrows(ConfigException.class, () -> SnapTrial.fromConfigs(Path.of(""), "coarse", null, Map.of("budget.maxWallSeconds", "0")),
                "a budget outside its range");
    }

    @Test
    void aSearchSpaceBeyondABoneSpeedOfTwoMetresASecondIsRefused() {
        StudyConfig c = StudyConfig.parse(Json.parse("space.json", """
                {"objectives": [{"name": "objective", "direction": "minimize"}],
                 "params": [{"name": "t0", "low": 0.0, "high": 0.05}, {"name": "t1", "low": 0.1, "high": 0.15},
                            {"name": "vp", "low": 0.002, "high": 0.005}, {"name": "t2", "low": 0.15, "high": 0.25},
                            {"name": "t3", "low": 0.3, "high": 0.45}, {"name": "vs", "low": 0.002, "high": 1e6}],
                 "parallelTrials": 1}
                """));
        SnapTrial trial = SnapTrial.fromConfigs(Path.of(""), "coarse", null);
        ConfigException e = assertThrows(ConfigException.class, () -> trial.checkSearchSpace(c, "space.json"));
        assertEquals("space.json: params: vs's high must be <= 2.0 m/s (a flick of the finger), got 1000000.0", e.getMessage());
    }
}
