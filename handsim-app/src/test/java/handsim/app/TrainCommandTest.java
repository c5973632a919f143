package handsim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.CatchStyle;
import handsim.control.ControllerConfig;
import handsim.spec.RunConfigs;
import handsim.train.TrainConfig;
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
        ControllerConfig shipped = TrainCommand.environments(flip.run(), TrainCommand.configs(flip.run())).tasks().get().controller(base);
        assertTrue(shipped.armRest().isEmpty(), "no arm rest");
        assertEquals(new CatchStyle(0, 0.7), shipped.catchAfterThrow().orElseThrow(), "the run's catch");

        ObjectNode file = (ObjectNode) Json.load(Home.resolve("configs/train/flip.json")).node().deepCopy();
        ((ObjectNode) file.get("run").get("taskSet")).remove("objects.can.armRest");
        TrainConfig withRest = TrainConfig.parse(Json.of("flip.json", file));
        ControllerConfig resting = TrainCommand.environments(withRest.run(), TrainCommand.configs(withRest.run())).tasks().get()
                .controller(base);
        assertTrue(resting.armRest().isPresent(), "run.taskSet without the arm rest's null: the task's arm rest (configs/tasks/flip.json)");
    }

    @Test
    void aRunsStepperOverridesThePhysicsConfigsAndABadOneIsRefusedByName() {
        // run.stepper (optional): the constrained step of the run's physics, in place of configs/sim.json's solver.stepper
        ObjectNode file = (ObjectNode) Json.load(Home.resolve("configs/train/height.json")).node().deepCopy();
        ((ObjectNode) file.get("run")).remove("stepper"); // the shipped config names quickStep
        TrainConfig plain = TrainConfig.parse(Json.of("height.json", file));
        assertEquals(null, plain.run().stepper());
        assertEquals(Wiring.simConfig().stepper(), TrainCommand.configs(plain.run()).sim().stepper(), "absent: configs/sim.json's");
        for (String stepper : new String[] {"handsim", "ode4j"}) {
            ((ObjectNode) file.get("run")).put("stepper", stepper);
            TrainConfig run = TrainConfig.parse(Json.of("height.json", file));
            assertEquals(stepper, TrainCommand.configs(run.run()).sim().stepper().label());
            // recorded in the run's spec as the physics' document read, which a resumed run replays
            RunConfigs configs = TrainCommand.configs(run.run());
            configs.sim();
            assertEquals(stepper, configs.files().toJson().get(RunConfigs.SIM).get("solver").get("stepper").asText());
        }
        ((ObjectNode) file.get("run")).put("stepper", "bullet");
        var e = org.junit.jupiter.api.Assertions.assertThrows(handsim.config.ConfigException.class,
                () -> TrainConfig.parse(Json.of("height.json", file)));
        assertTrue(e.getMessage().contains("stepper") && e.getMessage().contains("bullet"), e.getMessage());
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
