package handsim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.CatchStyle;
import handsim.control.ControllerConfig;
import handsim.train.TrainConfig;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The environments a training run plays in: its task as the run's config sets it. */
@Tag("fast")
class TrainCommandTest {

    private final ControllerConfig base = ControllerConfig.load(Home.resolve("configs/controller.json"));

    @Test
    void aFlipRunTrainsWithTheCatchAndTheArmRestItsConfigSays() {
        // configs/train/flip.json: the controller's own catch and no arm rest, as the shipped can policy was trained
        TrainConfig flip = TrainConfig.load(Home.resolve("configs/train/flip.json"));
        ControllerConfig shipped = TrainCommand.environments(flip.run(), TestSupport.model()).tasks().get().controller(base);
        assertTrue(shipped.armRest().isEmpty(), "no arm rest");
        assertEquals(new CatchStyle(0, 0.7), shipped.catchAfterThrow().orElseThrow(), "the run's catch");

        TrainConfig withRest = TrainConfig.parse(Json.of("set", Json.withOverrides("flip.json",
                Json.load(Home.resolve("configs/train/flip.json")).node(), Map.of("run.armRest", "true"))));
        ControllerConfig resting = TrainCommand.environments(withRest.run(), TestSupport.model()).tasks().get().controller(base);
        assertTrue(resting.armRest().isPresent(), "run.armRest true: the task's arm rest (configs/tasks/flip.json)");
        assertEquals(shipped.catchAfterThrow(), resting.catchAfterThrow(), "the catch stays the run's");
    }

    @Test
    void aRunRecordsACommandLineAShellReadsBack() {
        // plain words as they are; a JSON value and a quote inside single quotes (POSIX sh)
        assertEquals("scripts/handsim train --config configs/train/flip.json --set run.armRest=true "
                + "--set 'run.catch={\"planeShift\": 0}' --set 'run.name=it'\\''s'",
                RunOptions.commandLine("train", java.nio.file.Path.of("configs/train/flip.json"),
                        java.util.List.of("run.armRest=true", "run.catch={\"planeShift\": 0}", "run.name=it's")));
    }
}
