package handsim.app;

import handsim.model.HandModel;
import handsim.scene.HeldBallScene;
import handsim.scene.InteractiveScene;
import handsim.scene.Scene;
import handsim.scene.SceneSetup;
import handsim.scene.SwitchingScene;
import handsim.sim.Simulator;
import handsim.task.Goal;
import handsim.task.HeightGoals;
import handsim.task.HeightTask;
import handsim.task.HeldBallScenario;
import handsim.task.ServoLoop;
import handsim.viewer.ViewerConfig;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * The scene a headless run shows ({@code render}, {@code export}), and for how long: without
 * {@code --controller}, {@code --task} or {@code --plan} the foundation's held ball; with any of
 * them the scene {@code view} shows for the same task, object, controller and seed
 * ({@link ShippedScenes}: the learned controller plays {@code --policy} or the shipped policy),
 * with its goal.
 */
final class SceneOptions {

    @Mixin
    ControllerOptions who;

    @Mixin
    EpisodeOptions episodeOptions;

    @Option(names = "--seconds", paramLabel = "S", defaultValue = "2", description = "simulated seconds (default: ${DEFAULT-VALUE})")
    double seconds;

    @Option(names = "--throw-height", paramLabel = "H", defaultValue = "1.2", description = "height task: apex goal, m")
    double throwHeight;

    /**
     * Refuses a duration out of (0, 600] s, a goal height the height task does not allow, a
     * misplaced opening or rest policy and a bad --task-set.
     */
    void validate() {
        who.validateSceneOptions();
        if (!(seconds > 0 && seconds <= 600)) {
            throw new IllegalArgumentException("--seconds must be in (0, 600], got " + seconds);
        }
        HeightTask.Config height = who.choice().configs().height().config();
        if (!height.allowsGoal(throwHeight)) {
            throw new IllegalArgumentException("--throw-height must be in " + height.goalLimits() + ", got " + throwHeight);
        }
    }

    /** The scene asked for; {@code command} names the command in the notes printed. */
    Scene open(String command, ViewerConfig viewerConfig) {
        if (!who.given()) {
            if (!episodeOptions.object.equals("sphere")) {
                throw new IllegalArgumentException("--object goes with --task or --controller (the held ball is a sphere), got "
                        + episodeOptions.object);
            }
            HandModel model = Wiring.model(null);
            Simulator sim = Wiring.simulator(model, Wiring.simConfig());
            return new HeldBallScene(new HeldBallScenario(new ServoLoop(sim, Wiring.pd(model)), Wiring.object("sphere"), 0.2, episodeOptions.seed));
        }
        SceneSetup wanted = new SceneSetup(who.task(), episodeOptions.object, who.controller(), episodeOptions.seed);
        SwitchingScene scene = ViewerSession.scene(command, wanted, HeightGoals.fixed(throwHeight), who.choice(), viewerConfig);
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
