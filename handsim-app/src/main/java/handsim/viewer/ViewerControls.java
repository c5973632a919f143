package handsim.viewer;

import static org.lwjgl.glfw.GLFW.*;

import handsim.scene.LiveRun;
import java.util.List;

/**
 * What the keyboard and the mouse do, without a window: GLFW's events go in, and out come
 * camera moves, commands to the {@link LiveRun}, overlay switches and requests the viewer
 * carries out after drawing (screenshot, recording frames or glTF, quit). Mouse: left drag orbits, right drag
 * (or shift + left) pans, middle drag and the wheel zoom.
 */
final class ViewerControls {

    /** A middle-button drag of this many pixels zooms as much as one wheel notch. */
    static final double PIXELS_PER_ZOOM_NOTCH = 20;

    private final LiveRun run;
    private final Camera camera;
    private final ViewerConfig.Pacing pacing;
    boolean help;
    boolean follow;
    boolean trail = true;
    boolean axes;
    boolean screenshotRequested;
    boolean recordToggleRequested;
    boolean gltfToggleRequested;
    boolean quitRequested;
    private int speedIndex;
    private boolean paused;
    private int dragButton = -1;
    private boolean dragPans;
    private double lastX = Double.NaN, lastY = Double.NaN;

    ViewerControls(LiveRun run, Camera camera, ViewerConfig.Pacing pacing) {
        this.run = run;
        this.camera = camera;
        this.pacing = pacing;
    }

    /** A GLFW key event ({@code action}: GLFW_PRESS, GLFW_REPEAT or GLFW_RELEASE). */
    void key(int key, int action, int mods) {
        ViewerAction a = ViewerAction.forKey(key);
        if (a != null && (action == GLFW_PRESS || action == GLFW_REPEAT && a.repeats())) {
            perform(a);
        }
    }

    void perform(ViewerAction a) {
        if (a.command != null) {
            run.command(a.command);
            return;
        }
        switch (a) {
            case HELP -> help = !help;
            case PAUSE -> {
                paused = !paused;
                run.setPaused(paused);
            }
            case STEP -> {
                paused = true;
                run.step(pacing.singleStepSeconds());
            }
            case SLOW_MOTION -> {
                List<Double> speeds = pacing.slowMotion();
                speedIndex = (speedIndex + 1) % speeds.size();
                run.setSpeed(speeds.get(speedIndex));
            }
            case FOLLOW -> follow = !follow;
            case RESET_CAMERA -> {
                follow = false;
                camera.reset();
            }
            case TRAIL -> trail = !trail;
            case AXES -> axes = !axes;
            case RECORD -> recordToggleRequested = true;
            case RECORD_GLTF -> gltfToggleRequested = true;
            case SCREENSHOT -> screenshotRequested = true;
            case QUIT -> quitRequested = true;
            default -> throw new IllegalStateException("unhandled viewer action " + a);
        }
    }

    /** Keeps the pause toggle in step with the run (which pauses itself after an error). */
    void syncPaused(boolean runPaused) {
        paused = runPaused;
    }

    void mouseButton(int button, int action, int mods) {
        if (action == GLFW_PRESS && dragButton < 0) {
            dragButton = button;
            dragPans = button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_LEFT && (mods & GLFW_MOD_SHIFT) != 0;
        } else if (action == GLFW_RELEASE && button == dragButton) {
            dragButton = -1;
        }
    }

    void cursor(double x, double y) {
        double dx = Double.isNaN(lastX) ? 0 : x - lastX, dy = Double.isNaN(lastY) ? 0 : y - lastY;
        lastX = x;
        lastY = y;
        if (dragButton < 0) {
            return;
        }
        if (dragPans) {
            camera.pan(dx, dy);
        } else if (dragButton == GLFW_MOUSE_BUTTON_MIDDLE) {
            camera.zoom(-dy / PIXELS_PER_ZOOM_NOTCH);
        } else {
            camera.orbit(dx, dy);
        }
    }

    void scroll(double notches) {
        camera.zoom(notches);
    }
}
