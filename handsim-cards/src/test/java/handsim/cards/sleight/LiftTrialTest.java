package handsim.cards.sleight;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.cards.study.StudyConfig;
import handsim.config.ConfigException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A reduced Double Lift trial (four card-stock cards of 7 x 4 cells, three of them free, coarse
 * fingertips, 0.4 s; cards of 5 x 3 cells do not reach the pads): pinching the top of the stack
 * and lifting raises the top two cards and leaves the third where it lay, no surface ever touches
 * another, and fingers that never close touch nothing. The tests share one rested stack, warmed
 * up by whichever runs first.
 */
@Tag("fast")
class LiftTrialTest {

    /** The checkpoint of the reduced stack, shared by the tests (its key is the same for all). */
    @TempDir
    static Path checkpoints;

    static LiftTrial reduced(Path checkpoints) {
        return LiftTrial.fromConfigs(Path.of("."), null, "cardStock", reducedSettings(), checkpoints);
    }

    static Map<String, String> reducedSettings() {
        Map<String, String> o = new LinkedHashMap<>();
        o.put("double-lift.stack.count", "4");
        o.put("double-lift.fingertip.mesh", "\"coarse\"");
        o.put("double-lift.trial.duration", "0.4");
        o.put("double-lift.trial.restAfterLift", "0.05");
        o.put("double-lift.card.cells", "[7, 4]");
        return o;
    }

    /** Pinch 0.48 mm (0.2 mm of it closes the gap) in [0, 0.08] s, lift 5 mm in [0.1, 0.3] s, from the top of the stack. */
    static LiftParams pinchAndLift(double hStart, double vp) {
        return new LiftParams(hStart, new BoneWindows(0, 0.08, vp, 0.1, 0.3, 0.025));
    }

    @Test
    void pinchingTheTopOfTheStackLiftsTheTopTwoCardsAndLeavesTheThird() {
        LiftTrial trial = reduced(checkpoints);
        LiftResult r = trial.run(pinchAndLift(0, 0.006), null);
        assertTrue(r.cost().minGap() > 0, "minimum gap " + r.cost().minGap());
        // the pads reach the top two cards' ends: both rise, by less than the bones' 5 mm (they slip)
        assertTrue(r.h1() > 1e-3 && r.h1() < 5e-3, "top card rose " + r.h1() + " m");
        assertTrue(r.h2() > 1e-3 && r.h2() < 5e-3, "second card rose " + r.h2() + " m");
        // the third card lies below the pads' reach and stays (well within the study's 0.5 mm tolerance)
        assertTrue(r.d3() < 1e-4, "third card moved " + r.d3() + " m");
        assertArrayEquals(new double[] {Math.abs(r.h1() - 0.005), Math.abs(r.h2() - 0.005), r.d3()}, r.values(), 0.0);
        assertEquals(40, r.cost().steps());
    }

    @Test
    @Tag("slow") // a second trial; the fast tests keep the lift above
    void fingersThatNeverCloseTouchNothing() {
        LiftTrial trial = reduced(checkpoints);
        // no pinch: the skins stay 0.2 mm off the cards' ends while the bones rise 5 mm
        LiftResult r = trial.run(pinchAndLift(0, 0), null);
        // the resting cards stay put: within a micrometre (a 200th of a card's thickness) of where they lay
        assertTrue(Math.abs(r.h1()) < 1e-6 && Math.abs(r.h2()) < 1e-6 && r.d3() < 1e-6, "h1 " + r.h1() + ", h2 " + r.h2() + ", d3 " + r.d3());
        assertTrue(r.cost().minGap() > 0);
    }

    @Test
    void searchSpacesThatAllowInvalidTrialsAreRefused() {
        LiftTrial trial = reduced(checkpoints);
        String objectives = "\"objectives\": [{\"name\": \"h1\", \"direction\": \"minimize\"}, {\"name\": \"h2\", \"direction\": \"minimize\"},"
                + " {\"name\": \"d3\", \"direction\": \"minimize\"}],";
        String params = "\"params\": [{\"name\": \"hStart\", \"low\": 0, \"high\": 0.001}, {\"name\": \"t0\", \"low\": 0, \"high\": 0.02},"
                + " {\"name\": \"t1\", \"low\": 0.05, \"high\": 0.08}, {\"name\": \"vp\", \"low\": 0.002, \"high\": 0.008},"
                + " {\"name\": \"t2\", \"low\": 0.1, \"high\": 0.15}, {\"name\": \"t3\", \"low\": 0.2, \"high\": HIGH},"
                + " {\"name\": \"vs\", \"low\": 0.01, \"high\": 0.05}], \"parallelTrials\": 2";
        trial.checkSearchSpace(StudyConfig.parse(handsim.config.Json.parse("ok", "{" + objectives + params.replace("HIGH", "0.35") + "}")), "ok");
        // the lift could end 0.05 s before the 0.4 s trial, where the pair must rest 0.05 s: t3 at most 0.35
        ConfigException late = assertThrows(ConfigException.class, () -> trial.checkSearchSpace(
                StudyConfig.parse(handsim.config.Json.parse("late", "{" + objectives + params.replace("HIGH", "0.36") + "}")), "late"));
        assertTrue(late.getMessage().contains("t3"), late.getMessage());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> trial.run(new LiftParams(0, new BoneWindows(0, 0.08, 0.006, 0.1, 0.38, 0.025)), null));
        assertTrue(e.getMessage().startsWith("t3 must be <="), e.getMessage());
    }

    @Test
    @Tag("slow") // a third trial, stopped by its budget
    void startHeightsAndSpeedsBeyondAFingersReachAreRefusedAndATrialPastItsBudgetStops() {
        LiftTrial trial = reduced(checkpoints);
        // 3 cm above the stack: farther than the fingertip's half-height and the stack's height (LiftParams.MAX_START_HEIGHT)
        IllegalArgumentException high = assertThrows(IllegalArgumentException.class,
                () -> trial.run(pinchAndLift(0.03, 0.006), null));
        assertEquals("hStart must be a height in [-0.02, 0.02] m, got 0.03", high.getMessage());
        // a lift at 1e6 m/s: faster than a flick of the finger (2 m/s)
        IllegalArgumentException fast = assertThrows(IllegalArgumentException.class,
                () -> trial.run(new LiftParams(0, new BoneWindows(0, 0.08, 0.006, 0.1, 0.3, 1e6)), null));
        assertEquals("vs must be a speed in [0, 2] m/s, got 1000000", fast.getMessage());
        // a Newton iteration a simulated step (100 a simulated second, 40 for the 0.4 s trial): the pinch's steps take more
        Map<String, String> o = reducedSettings();
        LiftTrial budgeted = LiftTrial.fromConfigs(Path.of("."), null, "cardStock", o, checkpoints);
        budgeted.restedStack(); // the warm-up within the shipped budget
        o.put("budget.maxNewtonIterationsPerSecond", "100");
        LiftTrial tight = LiftTrial.fromConfigs(Path.of("."), null, "cardStock", o, checkpoints);
        handsim.cards.contact.BudgetExceeded e = assertThrows(handsim.cards.contact.BudgetExceeded.class,
                () -> tight.run(pinchAndLift(0, 0.006), null));
        assertTrue(e.getMessage().matches("more than 40 Newton iterations by step \\d+ .*"), e.getMessage());
        assertEquals(100.0, tight.inputs().get("budget").get("maxNewtonIterationsPerSecond").asDouble(), "the budget is recorded with the trial");
    }
}
