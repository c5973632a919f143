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
import handsim.viewer.Camera;
import handsim.viewer.FrameFolder;
import handsim.viewer.OffscreenRenderer;
import handsim.viewer.ViewerConfig;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code handsim render}: a headless run written as numbered PNG frames ({@code 00000.png}, ...),
 * from the home camera of {@code configs/viewer.json}, drawn by the viewer's renderer. Without
 * {@code --controller} or {@code --task} the foundation's held-ball scene; with either, the scene
 * {@code view} shows for the same task, object, controller and seed ({@link ShippedScenes}: the
 * learned controller plays {@code --policy} or the shipped policy), with its goal.
 */
@Command(name = "render", mixinStandardHelpOptions = true,
        description = "Write a headless run as PNG frames DIR/00000.png, 00001.png, ... (make a video with "
                + "ffmpeg -framerate F -i DIR/%%05d.png out.mp4). Needs an X display; the launcher uses xvfb-run without one.")
final class RenderCommand implements Callable<Integer> {

    @Option(names = "--out", paramLabel = "DIR", required = true, description = "folder for the frames")
    Path out;

    @Option(names = "--seconds", paramLabel = "S", defaultValue = "2", description = "simulated seconds (default: ${DEFAULT-VALUE})")
    double seconds;

    @Option(names = "--fps", paramLabel = "F", defaultValue = "30", description = "frames per simulated second (default: ${DEFAULT-VALUE})")
    int fps;

    @Option(names = "--width", defaultValue = "960", description = "image width in pixels (default: ${DEFAULT-VALUE})")
    int width;

    @Option(names = "--height", defaultValue = "720", description = "image height in pixels (default: ${DEFAULT-VALUE})")
    int height;

    @Option(names = "--seed", defaultValue = "1", description = "seed (default: ${DEFAULT-VALUE})")
    long seed;

    @Option(names = "--task", description = "height, box or flip: render that task's catch-and-throw loop instead of "
            + "the held ball (default with --controller: height)")
    String task;

    @Option(names = "--controller", description = "nominal or learned: render the catch-and-throw loop instead of the "
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

    @Override
    public Integer call() throws Exception {
        if (!(seconds > 0 && seconds <= 600)) {
            throw new IllegalArgumentException("--seconds must be in (0, 600], got " + seconds);
        }
        if (fps < 1 || fps > 240) {
            throw new IllegalArgumentException("--fps must be in [1, 240], got " + fps);
        }
        if (width < 16 || width > 8192 || height < 16 || height > 8192) {
            throw new IllegalArgumentException("--width and --height must be in [16, 8192] pixels, got " + width + " x " + height);
        }
        new OutputPaths().folder("--out", out).check();
        if (!ViewerSession.hasDisplay()) {
            throw new IllegalArgumentException("no X display (DISPLAY is not set): render draws with OpenGL "
                    + "(scripts/handsim render runs it under xvfb-run)");
        }
        int frames = (int) Math.round(seconds * fps);
        ViewerConfig config = ViewerSession.config();
        try (Scene scene = scene(config); OffscreenRenderer renderer = new OffscreenRenderer(width, height, config);
                FrameFolder folder = new FrameFolder(out)) {
            Camera camera = new Camera(config.camera());
            long t0 = System.nanoTime();
            for (int f = 0; f < frames; f++) {
                Goal goal = scene instanceof InteractiveScene s ? s.goal() : new Goal.None();
                var image = renderer.render(scene.snapshot(), camera, r -> r.drawGoal(goal));
                folder.add(() -> image);
                if (f % Math.max(1, fps / 2) == 0 || f == frames - 1) {
                    System.out.printf("frame %d/%d  t=%.2f s  %s%n", f + 1, frames, scene.time(), scene.status());
                }
                scene.advance(1.0 / fps);
            }
            System.out.printf("wrote %d frames to %s (%.0f ms per frame)%n", frames, out, (System.nanoTime() - t0) / 1e6 / frames);
        }
        return 0;
    }

    private Scene scene(ViewerConfig viewerConfig) {
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
        SwitchingScene scene = ViewerSession.scene("render", wanted, HeightGoals.fixed(throwHeight), policy, plan, viewerConfig);
        SceneSetup shown = scene.shown();
        System.out.println("handsim render: " + shown.task() + " task, " + shown.object() + ", " + shown.controller()
                + " controller, seed " + shown.seed());
        return scene;
    }
}
