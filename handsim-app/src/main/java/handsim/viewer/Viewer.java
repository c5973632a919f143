package handsim.viewer;

import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.opengl.GL11.*;

import handsim.scene.LiveFrame;
import handsim.scene.LiveRun;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.Locale;
import java.util.concurrent.locks.LockSupport;
import org.lwjgl.BufferUtils;
import org.lwjgl.glfw.Callbacks;

/**
 * The interactive viewer: a window that draws the newest {@link LiveFrame} of a {@link LiveRun}
 * as often as it can (or at the display's refresh with vsync), with a heads-up display, mouse
 * camera and the keys of {@link ViewerAction}. It only draws and forwards commands: the run
 * advances the scene on its own thread, paced by simulated time, whatever the frame rate.
 */
public final class Viewer implements AutoCloseable {

    /** Frames drawn over wall seconds, and the simulated seconds the run advanced meanwhile. */
    public record Stats(int frames, double wallSeconds, double simSeconds) {
        public double fps() {
            return frames / wallSeconds;
        }

        public double realTimeFactor() {
            return simSeconds / wallSeconds;
        }
    }

    /** Wall seconds over which the displayed frame rate is measured. */
    static final double FPS_WINDOW = 0.5;
    /** How long the viewer sleeps at a time while it leaves the cores to a lagging simulation. */
    static final long YIELD_SLICE_NANOS = 500_000;
    private static final DateTimeFormatter STAMP = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss-SSS");

    private final ViewerConfig config;
    private final LiveRun run;
    private final Path pictures;
    private final GlWindow window;
    private final SceneRenderer renderer;
    private final Hud hud;
    private final Camera camera;
    private final ViewerControls controls;
    private final Trail trail;
    private ByteBuffer pixels = BufferUtils.createByteBuffer(4);
    private LiveFrame drawn;
    private FrameFolder recording;
    private double nextRecordTime;
    private GltfRecording gltf;
    /** Writes a finished glTF recording off the drawing thread; null when none is being written. */
    private Thread gltfWriter;
    private final String title;
    private double fps = Double.NaN;
    private double clock;

    /**
     * Opens the window. Screenshots and recordings go under {@code pictures}; {@code vsync} false
     * draws as fast as possible (benchmarks).
     */
    public Viewer(ViewerConfig config, LiveRun run, Path pictures, String title, boolean vsync) {
        this.config = config;
        this.run = run;
        this.pictures = pictures;
        this.title = title;
        window = new GlWindow(config.window().width(), config.window().height(), title, true);
        glfwSwapInterval(vsync ? 1 : 0);
        renderer = new SceneRenderer(config);
        hud = new Hud(config);
        camera = new Camera(config.camera());
        controls = new ViewerControls(run, camera, config.pacing());
        trail = new Trail(config.overlays().trailSeconds());
        glfwSetKeyCallback(window.handle, (w, key, scancode, action, mods) -> controls.key(key, action, mods));
        glfwSetMouseButtonCallback(window.handle, (w, button, action, mods) -> controls.mouseButton(button, action, mods));
        glfwSetCursorPosCallback(window.handle, (w, x, y) -> controls.cursor(x, y));
        glfwSetScrollCallback(window.handle, (w, dx, dy) -> controls.scroll(dy));
    }

    /** Draws until the window is closed, Esc is pressed, or {@code maxFrames} frames (0: no limit). */
    public Stats run(int maxFrames) {
        return run(maxFrames, 0);
    }

    /**
     * Draws for {@code warmupSeconds} (while the JIT compiles the simulation's hot paths), then
     * until the window is closed, Esc is pressed, or {@code maxFrames} more frames (0: no limit).
     * The stats count the frames after the warm-up only.
     */
    public Stats run(int maxFrames, double warmupSeconds) {
        long start = System.nanoTime();
        double simStart = run.simulatedSeconds();
        long countFrom = start;
        boolean warm = warmupSeconds <= 0;
        double windowStart = 0, last = 0;
        int frames = 0, windowFrames = 0;
        while (!glfwWindowShouldClose(window.handle) && !controls.quitRequested && (maxFrames <= 0 || frames < maxFrames)) {
            if (!warm && (System.nanoTime() - start) / 1e9 >= warmupSeconds) {
                warm = true;
                countFrom = System.nanoTime();
                simStart = run.simulatedSeconds();
            }
            long frameStart = System.nanoTime();
            glfwPollEvents();
            clock = (frameStart - start) / 1e9;
            LiveFrame f = run.latest();
            controls.syncPaused(f.paused());
            for (String note; (note = run.pollNote()) != null; ) {
                hud.addNote(note, clock);
            }
            follow(f, clock - last);
            last = clock;
            draw(f);
            takePictures(f);
            glfwSwapBuffers(window.handle);
            yieldToSimulation(frameStart);
            frames += warm ? 1 : 0;
            windowFrames++;
            if (clock - windowStart >= FPS_WINDOW) {
                fps = windowFrames / (clock - windowStart);
                windowStart = clock;
                windowFrames = 0;
            }
        }
        double wall = (System.nanoTime() - countFrom) / 1e9;
        return new Stats(frames, wall, run.simulatedSeconds() - simStart);
    }

    /**
     * Physics first: while the run falls behind real time, frames come no faster than
     * {@code window.fpsWhenBehind}, so that drawing does not take the cores the simulation needs.
     */
    private void yieldToSimulation(long frameStart) {
        if (!run.behind()) {
            return;
        }
        long until = frameStart + (long) (1e9 / config.window().fpsWhenBehind());
        for (long now = System.nanoTime(); now < until && run.behind(); now = System.nanoTime()) {
            LockSupport.parkNanos(Math.min(until - now, YIELD_SLICE_NANOS));
        }
    }

    private void follow(LiveFrame f, double dt) {
        var object = f.snapshot().object();
        if (object.isEmpty()) {
            trail.clear();
            return;
        }
        trail.add(f.snapshot().time(), object.get().position());
        if (controls.follow) {
            camera.follow(object.get().position(), dt);
        }
    }

    private void draw(LiveFrame f) {
        int[] size = window.framebufferSize();
        if (size[0] == 0 || size[1] == 0) {
            return;
        }
        renderer.begin(camera, size[0], size[1]);
        renderer.drawWorld(f.snapshot());
        if (controls.trail) {
            renderer.drawTrail(trail, f.snapshot().time());
        }
        renderer.drawGoal(f.goal());
        if (controls.axes) {
            renderer.drawJointAxes(f.snapshot());
        }
        String frames = recording == null ? null : recording.count() + " frames → " + recording.dir().getFileName();
        String samples = gltf == null ? null : gltf.samples() + " glTF samples → " + gltf.file().getFileName();
        String rec = frames == null ? samples : samples == null ? frames : frames + ", " + samples;
        hud.draw(size[0], size[1], () -> Hud.rows(f, fps, rec), controls.help, clock);
        drawn = f;
    }

    private void takePictures(LiveFrame f) {
        if (controls.screenshotRequested) {
            controls.screenshotRequested = false;
            Path file = pictures.resolve("screenshots").resolve("handsim-" + LocalDateTime.now().format(STAMP) + ".png");
            run.report("screenshot: " + shortPath(writeScreenshot(file)));
        }
        if (controls.recordToggleRequested) {
            controls.recordToggleRequested = false;
            toggleRecording(f);
        }
        if (recording != null) {
            record(f.snapshot().time());
        }
        if (controls.gltfToggleRequested) {
            controls.gltfToggleRequested = false;
            toggleGltf();
        }
        if (gltf != null) {
            gltf.offer(f);
        }
    }

    /** Starts a glTF recording, or stops the one running and writes it on a thread of its own. */
    private void toggleGltf() {
        if (gltf == null) {
            try {
                gltf = new GltfRecording(pictures.resolve("recording__" + LocalDateTime.now().format(STAMP) + ".glb"), config, camera,
                        title);
                run.report("recording glTF into " + shortPath(gltf.file()));
            } catch (IllegalArgumentException e) {
                run.report("glTF recording failed: " + e.getMessage());
            }
            return;
        }
        GltfRecording done = gltf;
        gltf = null;
        finishGltfWriter();
        gltfWriter = new Thread(() -> writeGltf(done), "gltf-writer");
        gltfWriter.start();
    }

    private void writeGltf(GltfRecording done) {
        try {
            run.report(done.write() ? "recorded " + done.samples() + " glTF samples into " + shortPath(done.file())
                    : "glTF recording too short (fewer than two samples): nothing written");
        } catch (IOException | RuntimeException e) {
            run.report("glTF recording failed: " + e.getMessage());
        }
    }

    /** Waits for a glTF file still being written. */
    private void finishGltfWriter() {
        if (gltfWriter != null) {
            try {
                gltfWriter.join();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            gltfWriter = null;
        }
    }

    /**
     * Records a frame every 1/fps simulated seconds: on schedule the grid is kept; after a reset
     * (time going back) or when drawing fell behind, it starts again from now.
     */
    private void record(double t) {
        double period = 1.0 / config.recording().fps();
        if (t < nextRecordTime - period) {
            nextRecordTime = t;
        }
        if (t < nextRecordTime) {
            return;
        }
        nextRecordTime = t - nextRecordTime < period ? nextRecordTime + period : t + period;
        int[] size = window.framebufferSize();
        byte[] rgba = read(size[0], size[1]);
        recording.add(() -> FrameFolder.toImage(size[0], size[1], rgba));
    }

    private void toggleRecording(LiveFrame f) {
        try {
            if (recording == null) {
                recording = new FrameFolder(pictures.resolve("recording__" + LocalDateTime.now().format(STAMP)));
                nextRecordTime = f.snapshot().time();
                run.report("recording PNG frames into " + shortPath(recording.dir()));
            } else {
                FrameFolder done = recording;
                recording = null;
                done.close();
                String dir = shortPath(done.dir());
                run.report(String.format(Locale.ROOT, "recorded %d frames into %s (ffmpeg -framerate %d -i %s/%%05d.png out.mp4)",
                        done.count(), dir, config.recording().fps(), dir));
            }
        } catch (IOException e) {
            recording = null;
            run.report("recording failed: " + e.getMessage());
        }
    }

    /** {@code p} relative to the working directory when it lies under it (shorter on screen). */
    private static String shortPath(Path p) {
        Path cwd = Path.of("").toAbsolutePath(), abs = p.toAbsolutePath();
        return abs.startsWith(cwd) ? cwd.relativize(abs).toString() : abs.toString();
    }

    /** Draws the last frame again and writes it to {@code file} as a PNG; returns the file. */
    public Path writeScreenshot(Path file) {
        if (drawn == null) {
            draw(run.latest());
        } else {
            draw(drawn);
        }
        int[] size = window.framebufferSize();
        try {
            FrameFolder.writePng(FrameFolder.toImage(size[0], size[1], read(size[0], size[1])), file);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the screenshot " + file, e);
        }
        return file;
    }

    private byte[] read(int width, int height) {
        if (pixels.capacity() < width * height * 4) {
            pixels = BufferUtils.createByteBuffer(width * height * 4);
        }
        glReadBuffer(GL_BACK);
        return OffscreenRenderer.readPixels(width, height, pixels);
    }

    /** The frame drawn last (null before the first). */
    public LiveFrame lastDrawn() {
        return drawn;
    }

    public Camera camera() {
        return camera;
    }

    /** What the keys do (tests press them here). */
    ViewerControls controls() {
        return controls;
    }

    /** The drawable size in pixels. */
    public int[] size() {
        return window.framebufferSize();
    }

    /** The OpenGL renderer's name (e.g. Mesa's llvmpipe). */
    public String glRenderer() {
        return glGetString(GL_RENDERER);
    }

    /** Finishes the recordings in progress and closes the window (the run is the caller's). */
    @Override
    public void close() {
        if (gltf != null) {
            writeGltf(gltf);
            gltf = null;
        }
        finishGltfWriter();
        if (recording != null) {
            try {
                recording.close();
            } catch (IOException e) {
                System.err.println("handsim view: " + e.getMessage());
            }
        }
        hud.close();
        renderer.close();
        Callbacks.glfwFreeCallbacks(window.handle);
        window.close();
    }
}
