package handsim.viewer;

import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.opengl.GL11.*;

import java.util.List;

/**
 * Plays recorded frames of deforming surfaces (a card trial) in a window, looping, at {@code
 * speed} times real time. Drag with the left button to orbit, scroll to zoom; Escape closes.
 */
public final class SurfacePlayer {

    private SurfacePlayer() {
    }

    /** One recorded frame: its simulated time (s) and surfaces. */
    public record Frame(double time, List<SurfaceMesh> surfaces) {
    }

    /**
     * Opens a window and plays {@code frames} until closed, or for {@code maxFrames} drawn frames
     * when positive. Returns the number of frames drawn.
     */
    public static int play(String title, List<Frame> frames, Camera camera, ViewerConfig config, double speed, int maxFrames) {
        if (frames.isEmpty()) {
            throw new IllegalArgumentException("no frames to play");
        }
        try (GlWindow window = new GlWindow(960, 720, title, true); SceneRenderer scene = new SceneRenderer(config)) {
            glfwSwapInterval(1);
            double[] last = {Double.NaN, Double.NaN};
            boolean[] dragging = {false};
            glfwSetMouseButtonCallback(window.handle, (w, button, action, mods) -> {
                if (button == GLFW_MOUSE_BUTTON_LEFT) {
                    dragging[0] = action == GLFW_PRESS;
                }
            });
            glfwSetCursorPosCallback(window.handle, (w, x, y) -> {
                if (dragging[0] && !Double.isNaN(last[0])) {
                    camera.orbit(x - last[0], y - last[1]);
                }
                last[0] = x;
                last[1] = y;
            });
            glfwSetScrollCallback(window.handle, (w, dx, dy) -> camera.zoom(dy));
            glfwSetKeyCallback(window.handle, (w, key, code, action, mods) -> {
                if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) {
                    glfwSetWindowShouldClose(w, true);
                }
            });
            double start = frames.get(0).time();
            double span = frames.get(frames.size() - 1).time() - start;
            long t0 = System.nanoTime();
            int drawn = 0;
            while (!glfwWindowShouldClose(window.handle) && (maxFrames <= 0 || drawn < maxFrames)) {
                double t = start + ((System.nanoTime() - t0) * 1e-9 * speed) % Math.max(span, 1e-9);
                Frame f = frames.get(0);
                for (Frame candidate : frames) {
                    if (candidate.time() <= t) {
                        f = candidate;
                    }
                }
                int[] size = window.framebufferSize();
                scene.begin(camera, size[0], size[1]);
                scene.drawSurfaces(f.surfaces());
                glfwSwapBuffers(window.handle);
                glfwPollEvents();
                drawn++;
            }
            return drawn;
        }
    }
}
