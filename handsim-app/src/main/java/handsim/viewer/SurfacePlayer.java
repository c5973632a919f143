package handsim.viewer;

import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.opengl.GL11.*;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.util.List;
import org.lwjgl.BufferUtils;

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
     * when positive; writes the last frame drawn to {@code screenshot} (PNG) when not null. Returns
     * the number of frames drawn.
     */
    public static int play(String title, List<Frame> frames, Camera camera, ViewerConfig config, double speed, int maxFrames, Path screenshot) {
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
            Frame shown = frames.get(0);
            while (!glfwWindowShouldClose(window.handle) && (maxFrames <= 0 || drawn < maxFrames)) {
                double t = start + ((System.nanoTime() - t0) * 1e-9 * speed) % Math.max(span, 1e-9);
                Frame f = frames.get(0);
                for (Frame candidate : frames) {
                    if (candidate.time() <= t) {
                        f = candidate;
                    }
                }
                draw(window, scene, camera, f);
                glfwSwapBuffers(window.handle);
                glfwPollEvents();
                shown = f;
                drawn++;
            }
            if (screenshot != null) {
                int[] size = draw(window, scene, camera, shown);
                ByteBuffer pixels = BufferUtils.createByteBuffer(size[0] * size[1] * 4);
                glReadBuffer(GL_BACK);
                try {
                    FrameFolder.writePng(FrameFolder.toImage(size[0], size[1], OffscreenRenderer.readPixels(size[0], size[1], pixels)), screenshot);
                } catch (IOException e) {
                    throw new UncheckedIOException("cannot write the screenshot " + screenshot, e);
                }
            }
            return drawn;
        }
    }

    /** Draws one frame into the window's back buffer; returns the framebuffer size (pixels). */
    private static int[] draw(GlWindow window, SceneRenderer scene, Camera camera, Frame f) {
        int[] size = window.framebufferSize();
        scene.begin(camera, size[0], size[1]);
        scene.drawSurfaces(f.surfaces());
        return size;
    }
}
