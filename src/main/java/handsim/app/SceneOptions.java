package handsim.app;

import handsim.model.HandModel;
import handsim.sim.Simulator;
import handsim.task.Goal;
import handsim.task.HeightGoals;
import handsim.task.HeldBallScenario;
import handsim.task.HeldBallScene;
import handsim.task.InteractiveScene;
import handsim.task.Scene;
import handsim.task.SceneSetup;
import handsim.task.ServoLoop;
import handsim.task.SwitchingScene;
import handsim.viewer.ViewerConfig;
import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * The scene a headless run shows ({@code render}, {@code export}), and for how long: without
 * {@code --controller}, {@code --task} or {@code --plan} the foundation's held ball; with any of
 * them the scene {@code view} shows for the same task, object, controller and seed
 * ({@link ShippedScenes}: the learned controller plays {@code --policy} or the shipped policy),
 * with its goal.
 */
final class SceneOptions {

    @Option(names = "--seconds", paramLabel = "S", defaultValue = "2", description = "simulated seconds (default: ${DEFAULT-VALUE})")
    double seconds;

    @Option(names = "--seed", defaultValue = "1", description = "seed (default: ${DEFAULT-VALUE})")
    long seed;

    @Option(names = "--task", description = "height, box or flip: that task's catch-and-throw loop instead of "
            + "the held ball (default with --controller: height)")
    String task;

    @Option(names = "--controller", description = "nominal or learned: the catch-and-throw loop instead of the "
            + "held ball (default with --task: nominal)")
    String controller;

    @Option(names = "--policy", paramLabel = "FILE", description = "the learned controller's policy file (default: the "
            + "policy shipped for the task and object)")
    Path policy;

    @Option(names = "--plan", description = "flip: a throw planner chooses every throw, trying the controller's and variations "
            + "of it in a twin world first (configs/planner.json)")
    boolean plan;

    @Option(names = "--object", defaultValue = "sphere", description = "with --task or --controller: sphere, can, cuboid or club")
    String object;

    @Option(names = "--throw-height", paramLabel = "H", defaultValue = "1.2", description = "height task: apex goal, m")
    double throwHeight;

    /** Refuses a duration out of (0, 600] s. */
    void validate() {
        if (!(seconds > 0 && seconds <= 600)) {
            throw new IllegalArgumentException("--seconds must be in (0, 600], got " + seconds);
        }
    }

    /** The scene asked for; {@code command} names the command in the notes printed. */
    Scene open(String command, ViewerConfig viewerConfig) {
        if (controller == null && task == null && !plan) {
            if (!object.equals("sphere")) {
                throw new IllegalArgumentException("--object goes with --task or --controller (the held ball is a sphere), got "
                        + object);
            }
            HandModel model = Runtime.model(null);
            Simulator sim = Runtime.simulator(model, Runtime.simConfig());
            return new HeldBallScene(new HeldBallScenario(new ServoLoop(sim, Runtime.pd(model)), Runtime.object("sphere"), 0.2, seed));
        }
        SceneSetup wanted = new SceneSetup(task == null ? "height" : task, object, controller == null ? "nominal" : controller, seed);
        SwitchingScene scene = ViewerSession.scene(command, wanted, HeightGoals.fixed(throwHeight), policy, plan, viewerConfig);
        System.out.println("handsim " + command + ": " + describe(scene));
        return scene;
    }

    /** What a scene shows, in a few words (its task, object, controller and seed). */
    static String describe(Scene scene) {
        if (scene instanceof SwitchingScene s) {
            SceneSetup shown = s.shown();
            return shown.task() + " task, " + shown.object() + ", " + shown.controller() + " controller, seed " + shown.seed();
        }
        return "held sphere";
    }

    /** The scene's goal now (none for a scene without one). */
    static Goal goal(Scene scene) {
        return scene instanceof InteractiveScene s ? s.goal() : new Goal.None();
    }
}
