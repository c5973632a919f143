package handsim.app;

import handsim.train.ThrowPolicyFile;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import picocli.CommandLine.Option;

/**
 * Who throws, declared once for every command that runs a catch-and-throw loop ({@code
 * evaluate}, {@code view}, {@code render}, {@code export}): the task the throws aim at, the
 * nominal or a learned controller, the learned controller's policy (and the flip's opening
 * policy) and the throw planner. Left
 * out, an option is null (false for {@code --plan}); {@link #task()} and {@link #controller()}
 * give the defaults.
 */
final class ControllerOptions {

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

    @Option(names = "--plan", description = "flip: choose every throw by trying the policy's throw and variations of it in a twin "
            + "world first (handsim.evaluation.ThrowPlanner, settings in configs/planner.json); the hand then makes the best")
    boolean plan;

    /** --task, or height. */
    String task() {
        return task != null ? task : "height";
    }

    /** --controller, or nominal. */
    String controller() {
        return controller != null ? controller : "nominal";
    }

    /** Whether any of --task, --controller and --plan was given. */
    boolean given() {
        return task != null || controller != null || plan;
    }

    /** Refuses an unknown task or controller and a policy for the nominal controller. */
    void validate() {
        if (!List.of("height", "box", "flip").contains(task())) {
            throw new IllegalArgumentException("--task must be height, box or flip, got " + task);
        }
        if (!List.of("nominal", "learned").contains(controller())) {
            throw new IllegalArgumentException("--controller must be nominal or learned, got " + controller);
        }
        if (policy != null && !controller().equals("learned")) {
            throw new IllegalArgumentException("--policy goes with --controller learned");
        }
        validateOpening();
    }

    /** Refuses an opening policy where no learned flip is thrown, and one whose file does not exist (a typo). */
    void validateOpening() {
        if (openingPolicy != null && (!task().equals("flip") || !controller().equals("learned"))) {
            throw new IllegalArgumentException("--opening-policy goes with the flip task and --controller learned");
        }
        if (openingPolicy != null && !Files.isRegularFile(openingPolicy)) {
            throw new IllegalArgumentException("--opening-policy: no file " + openingPolicy);
        }
    }

    /** The learned controller's policy file: --policy, or the one shipped for the task and {@code object}. */
    Path policyFile(String object) {
        return policy != null ? policy : ThrowPolicyFile.shipped(task(), object);
    }
}
