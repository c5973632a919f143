package handsim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.control.ControllerConfig;
import java.util.Map;
import org.junit.jupiter.api.Test;

class TasksTest {

    private final Tasks shipped = TestSupport.tasks();

    @Test
    void overridesReplaceFieldsOfTheirTasksFileOnly() {
        // configs/tasks/height.json evaluates 10 throws an episode; configs/tasks/flip.json 100 loops
        Tasks varied = shipped.withOverrides("height", Map.of("evaluationThrows", "3"))
                .withOverrides("flip", Map.of("evaluationLoops", "7"));
        assertEquals(3, varied.height(null).config().evaluationThrows());
        assertEquals(shipped.height(null).config().evaluationThrows(), HeightTask.Config.parse(shipped.config("height")).evaluationThrows(),
                "the shipped tasks are left as they were");
        assertEquals(7, FlipTask.Config.parse(varied.config("flip")).evaluationLoops());
        assertEquals(100, FlipTask.Config.parse(shipped.config("flip")).evaluationLoops());
        Tasks again = varied.withOverrides("flip", Map.of("evaluationLoops", "9"));
        assertEquals(9, FlipTask.Config.parse(again.config("flip")).evaluationLoops(), "a later override of a field wins");
        assertEquals(3, again.height(null).config().evaluationThrows(), "and keeps the others");
    }

    @Test
    void nullLeavesAnOptionalFieldOutAndABadKeyIsRefusedByName() {
        // the can's arm rest (objects.can.armRest) is optional: null runs the flip task without it
        FlipTask withRest = (FlipTask) shipped.create("flip", "can");
        FlipTask without = (FlipTask) shipped.withOverrides("flip", Map.of("objects.can.armRest", "null")).create("flip", "can");
        ControllerConfig base = ControllerConfig.load(Home.resolve("configs/controller.json"));
        assertTrue(withRest.controller(base).armRest().isPresent(), "shipped with an arm rest");
        assertFalse(without.controller(base).armRest().isPresent());
        ConfigException misspelt = assertThrows(ConfigException.class,
                () -> shipped.withOverrides("flip", Map.of("objects.can.armRst", "1")).create("flip", "can"));
        assertTrue(misspelt.getMessage().contains("objects.can.armRst: unknown field"), misspelt.getMessage());
        ConfigException noObject = assertThrows(ConfigException.class,
                () -> shipped.withOverrides("flip", Map.of("objects.cann.armRest", "null")).create("flip", "can"));
        assertTrue(noObject.getMessage().contains("objects.cann.armRest") && noObject.getMessage().contains("no object \"cann\""),
                noObject.getMessage());
        assertThrows(IllegalArgumentException.class, () -> shipped.withOverrides("juggle", Map.of("a", "1")));
    }
}
