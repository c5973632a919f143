package handsim.app;

import handsim.scene.Scene;
import handsim.task.Goal;
import handsim.viewer.Camera;
import handsim.viewer.FrameFolder;
import handsim.viewer.OffscreenRenderer;
import handsim.viewer.ViewerConfig;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code handsim render}: a headless run written as numbered PNG frames ({@code 00000.png}, ...),
 * from the home camera of {@code configs/viewer.json}, drawn by the viewer's renderer, of the
 * scene {@link SceneOptions} name (the held ball, or the scene {@code view} shows for the same
 * task, object, controller and seed, with its goal).
 */
@Command(name = "render", mixinStandardHelpOptions = true,
        description = "Write a headless run as PNG frames DIR/00000.png, 00001.png, ... (make a video with "
                + "ffmpeg -framerate F -i DIR/%%05d.png out.mp4). Needs an X display; the launcher uses xvfb-run without one. "
                + "With --scene snap|double-lift, a recorded card trial's frames and strip.png as cards snap|lift --out draws them.")
final class RenderCommand implements Callable<Integer> {

    @Option(names = "--out", paramLabel = "DIR", required = true, description = "folder for the frames")
    Path out;

    @Option(names = "--fps", paramLabel = "F", defaultValue = "30", description = "frames per simulated second (default: ${DEFAULT-VALUE})")
    int fps;

    @Option(names = "--width", defaultValue = "960", description = "image width in pixels (default: ${DEFAULT-VALUE})")
    int width;

    @Option(names = "--height", defaultValue = "720", description = "image height in pixels (default: ${DEFAULT-VALUE})")
    int height;

    @Mixin
    SceneOptions scene;

    @Mixin
    CardsSceneChoice cards;

    @Override
    public Integer call() throws Exception {
        if (cards.given()) {
            return renderCards();
        }
        scene.validate();
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
        int frames = (int) Math.round(scene.seconds * fps);
        ViewerConfig config = ViewerSession.config();
        try (Scene shown = scene.open("render", config); OffscreenRenderer renderer = new OffscreenRenderer(width, height, config);
                FrameFolder folder = new FrameFolder(out)) {
            Camera camera = new Camera(config.camera());
            long t0 = System.nanoTime();
            for (int f = 0; f < frames; f++) {
                Goal goal = SceneOptions.goal(shown);
                var image = renderer.render(shown.snapshot(), camera, r -> r.drawGoal(goal));
                folder.add(() -> image);
                if (f % Math.max(1, fps / 2) == 0 || f == frames - 1) {
                    System.out.printf("frame %d/%d  t=%.2f s  %s%n", f + 1, frames, shown.time(), shown.status());
                }
                shown.advance(1.0 / fps);
            }
            System.out.printf("wrote %d frames to %s (%.0f ms per frame)%n", frames, out, (System.nanoTime() - t0) / 1e6 / frames);
        }
        return 0;
    }

    /** A recorded card trial drawn again (the sleight's view of configs/cards/views.json): DIR/frames/ and DIR/strip.png. */
    private int renderCards() throws Exception {
        Path file = cards.file(true);
        if (width < 16 || width > 8192 || height < 16 || height > 8192) {
            throw new IllegalArgumentException("--width and --height must be in [16, 8192] pixels, got " + width + " x " + height);
        }
        new OutputPaths().folder("--out", out).check();
        if (!ViewerSession.hasDisplay()) {
            throw new IllegalArgumentException("no X display (DISPLAY is not set): render draws with OpenGL "
                    + "(scripts/handsim render runs it under xvfb-run)");
        }
        handsim.cards.sim.Trajectory t = handsim.cards.sim.Trajectory.read(file);
        int n = CardsRecording.renderFrames(t, CardViews.of(cards.scene, ViewerSession.config()), out.resolve("frames"), width, height);
        CardsRecording.writeStrip(out.resolve("frames"), n, out.resolve("strip.png"));
        System.out.println("wrote " + n + " frames to " + out.resolve("frames") + " and " + out.resolve("strip.png"));
        return 0;
    }
}
