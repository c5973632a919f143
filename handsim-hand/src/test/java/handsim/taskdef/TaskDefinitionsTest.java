package handsim.taskdef;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.ConfigException;
import handsim.config.ConfigSet;
import handsim.control.ControllerConfig;
import handsim.evaluation.EvaluationRequest;
import handsim.math.Vec3;
import handsim.spec.RunConfigs;
import handsim.task.FlipTask;
import handsim.task.Goal;
import handsim.task.HeightGoals;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The registry of the tasks and what each definition decides: its file's fields, the evaluate options it takes, its goal's hooks. */
@Tag("fast")
class TaskDefinitionsTest {

    private static RunConfigs with(String task, Map<String, String> fields) {
        return new RunConfigs(ConfigSet.fromFiles(Map.of(TaskDefinitions.file(task), fields)));
    }

    @Test
    void overridesReplaceFieldsOfTheirTasksFileOnly() {
        // configs/tasks/height.json evaluates 10 throws an episode; configs/tasks/flip.json 100 loops
        RunConfigs varied = with("height", Map.of("evaluationThrows", "3"));
        assertEquals(3, varied.task("height").defaultEvaluationLoops());
        assertEquals(10, TestSupport.configs().task("height").defaultEvaluationLoops(), "the shipped task is left as it was");
        assertEquals(100, varied.task("flip").defaultEvaluationLoops(), "another task's file is read as it is");
        assertEquals(7, with("flip", Map.of("evaluationLoops", "7")).flip().defaultEvaluationLoops());
    }

    @Test
    void nullLeavesAnOptionalFieldOutAndABadKeyIsRefusedByName() {
        // the can's arm rest (objects.can.armRest) is optional: null runs the flip task without it
        FlipTask withRest = TestSupport.configs().flip().newTask("can");
        FlipTask without = with("flip", Map.of("objects.can.armRest", "null")).flip().newTask("can");
        ControllerConfig base = TestSupport.configs().controller();
        assertTrue(withRest.controller(base).armRest().isPresent(), "shipped with an arm rest");
        assertFalse(without.controller(base).armRest().isPresent());
        ConfigException misspelt = assertThrows(ConfigException.class,
                () -> with("flip", Map.of("objects.can.armRst", "1")).flip());
        assertTrue(misspelt.getMessage().contains("objects.can.armRst: unknown field"), misspelt.getMessage());
        ConfigException noObject = assertThrows(ConfigException.class,
                () -> with("flip", Map.of("objects.cann.armRest", "null")).flip());
        assertTrue(noObject.getMessage().contains("objects.cann.armRest") && noObject.getMessage().contains("no object \"cann\""),
                noObject.getMessage());
        IllegalArgumentException unknown = assertThrows(IllegalArgumentException.class, () -> TaskDefinitions.file("juggle"));
        assertTrue(unknown.getMessage().contains("height, box, flip"), unknown.getMessage());
    }

    @Test
    void onlyTheBoxEvaluatesTestsAndAnUnknownTaskIsRefused() {
        // the box's evaluation places the box --tests times (paper sec. 5.2); height and flip run --episodes
        assertTrue(TaskDefinitions.evaluatesTests("box"));
        assertFalse(TaskDefinitions.evaluatesTests("height"));
        assertFalse(TaskDefinitions.evaluatesTests("flip"));
        assertThrows(IllegalArgumentException.class, () -> TaskDefinitions.evaluatesTests("juggle"));
    }

    @Test
    void eachTaskRefusesTheEvaluateOptionsItDoesNotTake() {
        RunConfigs shipped = TestSupport.configs();
        assertThrows(IllegalArgumentException.class, () -> shipped.task("height").check(request("height", true, null, null)),
                "only the flip task is planned");
        assertThrows(IllegalArgumentException.class, () -> shipped.task("box").check(request("box", false, 2, null)),
                "a box trial has no copies");
        assertThrows(IllegalArgumentException.class, () -> shipped.task("flip").check(request("flip", false, null, 1.2)),
                "a flip has no height to aim at");
        // configs/tasks/height.json goalLimits (0.72, 3): 5 m is out
        assertThrows(IllegalArgumentException.class, () -> shipped.task("height").check(request("height", false, null, 5.0)));
        shipped.task("height").check(request("height", false, 3, 1.2));
        shipped.task("flip").check(request("flip", true, null, null));
        IllegalArgumentException sphere = assertThrows(IllegalArgumentException.class,
                () -> shipped.task("flip").check(new EvaluationRequest("flip", "sphere", "nominal", false, 1, 3, 1, 1, null, null, null,
                        1e-9, null, null, false)));
        assertTrue(sphere.getMessage().contains("sphere"), sphere.getMessage());
    }

    private static EvaluationRequest request(String task, boolean plan, Integer copies, Double throwHeight) {
        return new EvaluationRequest(task, task.equals("flip") ? "can" : "sphere", "nominal", plan, 1, 3, 1, 1, throwHeight, null, copies,
                1e-9, null, null, false);
    }

    @Test
    void aScenesHooksDrawAndMoveEachTasksGoal() {
        RunConfigs shipped = TestSupport.configs();
        HeightGoals goals = HeightGoals.fixed(1.2);
        SteeredTask height = shipped.task("height").steered("sphere", goals, 0.8, 1.7);
        assertEquals(1.2, ((Goal.Height) height.goal().get()).height(), 1e-12);
        height.moveGoal().apply(new Vec3(0, 0.3, 0));
        assertEquals(1.5, goals.current(), 1e-12, "raised by 0.3 m");
        String capped = height.moveGoal().apply(new Vec3(0, 0.5, 0));
        assertEquals(1.7, goals.current(), 1e-12, "kept at the 1.7 m given as the highest: " + capped);
        assertTrue(height.moveGoal().apply(new Vec3(0.1, 0, 0)).contains("no box"), "the height goal does not move sideways");
        SteeredTask box = shipped.task("box").steered("sphere", goals, 0.8, 1.7);
        Vec3 before = ((Goal.Box) box.goal().get()).center();
        box.moveGoal().apply(new Vec3(0.05, 0, 0));
        assertEquals(before.x() + 0.05, ((Goal.Box) box.goal().get()).center().x(), 1e-12, "the box moves for the next throw-in");
        assertTrue(shipped.task("flip").steered("can", goals, 0.8, 1.7).goal().get() instanceof Goal.None);
    }
}
