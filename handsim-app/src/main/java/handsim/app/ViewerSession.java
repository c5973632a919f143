package handsim.app;

import handsim.config.Home;
import handsim.scene.HeightControl;
import handsim.scene.LiveRun;
import handsim.scene.SceneSetup;
import handsim.scene.SimClock;
import handsim.scene.SwitchingScene;
import handsim.task.HeightGoals;
import handsim.viewer.Viewer;
import handsim.viewer.ViewerConfig;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Opens the interactive viewer on a scene of {@link ShippedScenes}: {@code view} and
 * {@code demo} (with a display) both come here. The scene runs on a {@link LiveRun} thread;
 * the viewer draws on this one.
 */
final class ViewerSession {

    private ViewerSession() {
    }

    static ViewerConfig config() {
        return ViewerConfig.load(Home.resolve("configs/viewer.json"));
    }

    /**
     * The scene of {@link ShippedScenes} for {@code wanted} (a name it does not list is refused),
     * its fallback notes printed as {@code handsim COMMAND: ...}: what {@code view} shows and
     * {@code render} draws, with the policies and planner {@code who} chose.
     */
    static SwitchingScene scene(String command, SceneSetup wanted, HeightGoals goals, ControllerOptions.Choice who,
            ViewerConfig config) {
        SwitchingScene scene = new SwitchingScene(catalog(wanted, goals, who, config), wanted);
        scene.openingNotes().forEach(n -> System.out.println("handsim " + command + ": " + n));
        return scene;
    }

    /** The catalog of {@link ShippedScenes} for the options given; a name it does not list is refused. */
    private static ShippedScenes catalog(SceneSetup wanted, HeightGoals goals, ControllerOptions.Choice who, ViewerConfig config) {
        ViewerConfig.Goals g = config.goals();
        ShippedScenes catalog = new ShippedScenes(goals, new HeightControl(g.heightStep(), g.heightMin(), g.heightMax()), who);
        catalog.validate(wanted);
        return catalog;
    }

    /** True when an X display is set (GLFW needs one). */
    static boolean hasDisplay() {
        String d = System.getenv("DISPLAY");
        return d != null && !d.isBlank();
    }

    /**
     * Shows {@code wanted} until the window closes, or for {@code benchmarkFrames} frames drawn
     * as fast as possible (then prints the mean frame rate and real-time factor); writes a
     * screenshot of the last frame to {@code screenshot} if given.
     */
    static int open(String command, SceneSetup wanted, HeightGoals goals, ControllerOptions.Choice who, int benchmarkFrames,
            Path screenshot) {
        ViewerConfig config = config();
        catalog(wanted, goals, who, config); // bad names and settings are refused first
        if (!hasDisplay()) {
            throw new IllegalArgumentException("no X display (DISPLAY is not set): the viewer needs one "
                    + "(scripts/handsim demo runs headless; view --benchmark-frames N runs under xvfb-run)");
        }
        String prefix = "handsim " + command + ": ";
        SwitchingScene scene = scene(command, wanted, goals, who, config);
        ViewerConfig.Pacing p = config.pacing();
        SceneSetup shown = scene.shown();
        String title = "handsim — " + shown.task() + " task, " + shown.object() + ", " + shown.controller() + " controller";
        try (LiveRun run = new LiveRun(scene, new SimClock(p.maxLagSeconds()), p.minChunkSeconds(), p.maxChunkSeconds(),
                    n -> System.out.println(prefix + n));
                Viewer viewer = new Viewer(config, run, Home.resolve(config.recording().folder()), title,
                    config.window().vsync() && benchmarkFrames == 0)) {
            run.start();
            System.out.println(prefix + shown.task() + " task, " + shown.object() + ", " + shown.controller()
                    + " controller, seed " + shown.seed() + "; H in the window lists the keys, Esc quits");
            double warmup = benchmarkFrames > 0 ? config.benchmark().warmupSeconds() : 0;
            Viewer.Stats stats = viewer.run(benchmarkFrames, warmup);
            if (screenshot != null) {
                System.out.println(prefix + "screenshot " + viewer.writeScreenshot(screenshot));
            }
            if (benchmarkFrames > 0) {
                int[] size = viewer.size();
                System.out.printf(Locale.ROOT, "%sbenchmark: %d frames in %.2f s after a %.1f s warm-up: mean %.1f FPS; "
                        + "real-time factor %.3f (%.2f simulated s, h = %.1f ms); %dx%d, %s%n", prefix, stats.frames(),
                        stats.wallSeconds(), warmup, stats.fps(), stats.realTimeFactor(), stats.simSeconds(),
                        Wiring.simConfig().timeStep() * 1e3, size[0], size[1], viewer.glRenderer());
            }
        }
        return 0;
    }
}
