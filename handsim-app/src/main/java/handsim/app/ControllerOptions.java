package handsim.app;

import handsim.sim.SimConfig;
import handsim.spec.RunConfigs;
import handsim.taskdef.FlipDefinition;
import handsim.taskdef.HeightDefinition;
import handsim.taskdef.TaskDefinitions;
import handsim.train.ThrowPolicyFile;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import picocli.CommandLine.Option;

/**
 * Who throws, declared once for every command that runs a catch-and-throw loop ({@code
 * evaluate}, {@code view}, {@code render}, {@code export}): the task the throws aim at (and fields
 * of its file changed), the nominal or a learned controller, the learned controller's policy (and
 * the flip's opening and rest policies), the throw planner and the physics' constrained step. Left out, an option is null (false
 * for {@code --plan}, empty for {@code --task-set}); {@link #task()} and {@link #controller()}
 * give the defaults.
 */
final class ControllerOptions {

    /**
     * The policy files given for a learned controller (null: not given), whether the planner
     * chooses the flip's throws, per task name the fields of its file changed, and the
     * constrained step (null: configs/sim.json's): what the viewer's scenes are opened with.
     */
    record Choice(Path policy, Path opening, Path rest, boolean plan, Map<String, Map<String, String>> taskSet, String stepper) {

        /** Nothing given: the shipped policies, tasks and physics, no planner. */
        static final Choice SHIPPED = new Choice(null, null, null, false, Map.of(), null);

        /** The project's configs with {@link #taskSet} and {@link #stepper} applied: the shipped ones when nothing is set. */
        RunConfigs configs() {
            return taskSet.isEmpty() && stepper == null ? Wiring.shipped() : RunConfigs.ofProject(taskSet, stepper);
        }
    }

    @Option(names = "--task", description = "height, box or flip (default: height)")
    String task;

    @Option(names = "--controller", description = "nominal or learned (default: nominal)")
    String controller;

    @Option(names = "--policy", paramLabel = "FILE",
            description = "the learned controller's policy (default: the shipped models/policies/<task>-<object>.json)")
    Path policy;

    @Option(names = "--opening-policy", paramLabel = "FILE",
            description = "flip, learned controller: the policy for each episode's first throw, made from the object caught out "
                    + "of the launch (default: with the shipped policy, models/policies/flip-<object>-opening.json when it "
                    + "exists; with --policy, that policy makes every throw)")
    Path openingPolicy;

    @Option(names = "--rest-policy", paramLabel = "FILE",
            description = "flip, learned controller: the policy for the throws after the first made from the rest of the object in "
                    + "the hand it was trained for (its provenance's config.learnerThrows.rest) (default: with the shipped policy, "
                    + "models/policies/flip-<object>-rest.json when it exists; with --policy, none); with --plan, the planner's "
                    + "tries go on with it too")
    Path restPolicy;

    @Option(names = "--task-set", paramLabel = "KEY=VALUE", description = "change a field of the task's configs/tasks/TASK.json "
            + "for this run, e.g. --task-set 'objects.can.armRest.phases=[\"GOBACK\"]', or leave an optional one out with "
            + "--task-set objects.can.armRest=null (repeatable; dotted paths)")
    List<String> taskSet = List.of();

    @Option(names = "--stepper", paramLabel = "S",
            description = "the constrained step: handsim (handsim's own) or ode4j (ode4j's quickStep, with which the shipped "
                    + "policies were trained) (default: configs/sim.json's solver.stepper)")
    String stepper;

    @Option(names = "--plan", description = "flip: choose every throw by trying the policy's throw and variations of it in a twin "
            + "world first (handsim.planning.ThrowPlanner, settings in configs/planner.json); the hand then makes the best")
    boolean plan;

    /** --task, or height. */
    String task() {
        return task != null ? task : HeightDefinition.NAME;
    }

    /** --controller, or nominal. */
    String controller() {
        return controller != null ? controller : "nominal";
    }

    /** Whether any of --task, --controller and --plan was given. */
    boolean given() {
        return task != null || controller != null || plan;
    }

    /** Refuses an unknown task or controller and a policy for the nominal controller, and what {@link #validateSceneOptions} refuses. */
    void validate() {
        if (!TaskDefinitions.NAMES.contains(task())) {
            throw new IllegalArgumentException("--task must be one of " + String.join(", ", TaskDefinitions.NAMES) + ", got " + task);
        }
        if (!List.of("nominal", "learned").contains(controller())) {
            throw new IllegalArgumentException("--controller must be nominal or learned, got " + controller);
        }
        if (policy != null && !controller().equals("learned")) {
            throw new IllegalArgumentException("--policy goes with --controller learned");
        }
        validateSceneOptions();
    }

    /**
     * Refuses an unknown step, an opening or rest policy where no learned flip is thrown, one
     * whose file does not exist (a typo), and a --task-set the task's file does not take.
     */
    void validateSceneOptions() {
        if (stepper != null) {
            SimConfig.Stepper.named("--stepper", stepper);
        }
        refuseMisplaced("--opening-policy", openingPolicy);
        refuseMisplaced("--rest-policy", restPolicy);
        if (!taskSet.isEmpty()) {
            TaskDefinitions.check(task(), TaskDefinitions.read(task(), taskSetFields()));
        }
    }

    /** The --task-set fields, in order (empty when none). */
    Map<String, String> taskSetFields() {
        return RunOptions.keyValues("--task-set", taskSet);
    }

    private void refuseMisplaced(String option, Path file) {
        if (file != null && (!task().equals(FlipDefinition.NAME) || !controller().equals("learned"))) {
            throw new IllegalArgumentException(option + " goes with the flip task and --controller learned, got --task " + task()
                    + " --controller " + controller());
        }
        if (file != null && !Files.isRegularFile(file)) {
            throw new IllegalArgumentException(option + ": no file " + file);
        }
    }

    /** The options as the viewer's scenes take them. */
    Choice choice() {
        Map<String, String> fields = taskSetFields();
        return new Choice(policy, openingPolicy, restPolicy, plan, fields.isEmpty() ? Map.of() : Map.of(task(), fields), stepper);
    }

    /** The learned controller's policy file: --policy, or the one shipped for the task and {@code object}. */
    Path policyFile(String object) {
        return policy != null ? policy : ThrowPolicyFile.shipped(task(), object);
    }

    /**
     * The learned controller's policy for each episode's first throw: --opening-policy; else, with
     * the shipped policy, the opening one shipped beside it if there is one; else null (one policy
     * makes every throw).
     */
    Path openingFile(String object) {
        return givenOrBesideShipped(openingPolicy, ThrowPolicyFile.shippedOpening(task(), object));
    }

    /**
     * The learned controller's policy for the throws from one rest of the object: --rest-policy;
     * else, with the shipped policy, the rest policy shipped beside it if there is one; else null.
     */
    Path restFile(String object) {
        return givenOrBesideShipped(restPolicy, ThrowPolicyFile.shippedRest(task(), object));
    }

    /** {@code given} when given, with --policy or for the nominal controller; else {@code shipped} (null when none ships). */
    private Path givenOrBesideShipped(Path given, Path shipped) {
        return given != null || policy != null || !controller().equals("learned") ? given : shipped;
    }
}
