package handsim.app;

import handsim.scene.SceneSetup;
import handsim.task.HeightGoals;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code handsim view}: the interactive viewer. The scene is simulated at h = 0.2 ms in real
 * time on its own thread; the window draws it with a heads-up display (H lists the keys).
 */
@Command(name = "view", mixinStandardHelpOptions = true,
        description = "Watch the hand catch and throw in a window, in real time; change the goal, the object, the task "
                + "and the controller with keys (H lists them). Needs an X display.")
final class ViewCommand implements Callable<Integer> {

    /** Lenient here: an unknown task falls back to height, a learned controller without a usable policy to nominal, with a note. */
    @Mixin
    ControllerOptions who;

    @Mixin
    EpisodeOptions episodeOptions;

    @Option(names = "--heights", paramLabel = "LOW:HIGH", defaultValue = "1.1:1.3",
            description = "range of the random apex goals, m (default: ${DEFAULT-VALUE}); Up / Down move it")
    String heights;

    @Option(names = "--benchmark-frames", paramLabel = "N", defaultValue = "0",
            description = "draw N frames as fast as possible (no vsync), print the mean FPS and real-time factor, exit")
    int benchmarkFrames;

    @Option(names = "--screenshot", paramLabel = "FILE", description = "write the last frame drawn to FILE (PNG) on exit")
    Path screenshot;

    @Mixin
    CardsSceneChoice cards;

    @Override
    public Integer call() {
        if (benchmarkFrames < 0 || benchmarkFrames > 10_000_000) {
            throw new IllegalArgumentException("--benchmark-frames must be in [0, 10000000], got " + benchmarkFrames);
        }
        if (cards.given()) {
            new OutputPaths().file("--screenshot", screenshot).check();
            return CardsPlayback.play(cards.scene, cards.file(false), benchmarkFrames, screenshot);
        }
        who.validateSceneOptions();
        HeightGoals goals = DemoCommand.parseHeights(heights);
        new OutputPaths().file("--screenshot", screenshot).check();
        return ViewerSession.open("view", new SceneSetup(who.task(), episodeOptions.object, who.controller(), episodeOptions.seed), goals,
                who.choice(), benchmarkFrames, screenshot);
    }
}
