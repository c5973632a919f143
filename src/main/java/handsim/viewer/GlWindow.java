package handsim.viewer;

import static org.lwjgl.glfw.GLFW.*;

import org.lwjgl.glfw.GLFWErrorCallback;
import org.lwjgl.opengl.GL;

/**
 * A GLFW window with a current OpenGL context (compatibility profile, depth and stencil
 * buffers): visible for the viewer, hidden for off-screen rendering. Needs an X display; the
 * failure messages say how to get one.
 */
final class GlWindow implements AutoCloseable {

    final long handle;
    private final GLFWErrorCallback errors;

    GlWindow(int width, int height, String title, boolean visible) {
        errors = GLFWErrorCallback.createPrint(System.err).set();
        if (System.getenv("WAYLAND_DISPLAY") == null) {
            // X11 only: GLFW would otherwise probe for Wayland first and complain about it
            glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_X11);
        }
        if (!glfwInit()) {
            errors.free();
            throw new IllegalStateException("cannot open the X display (DISPLAY=" + System.getenv("DISPLAY")
                    + "): run under xvfb-run (apt-get install xvfb xauth libgl1-mesa-dri)");
        }
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_DEPTH_BITS, 24);
        glfwWindowHint(GLFW_STENCIL_BITS, 8);
        handle = glfwCreateWindow(width, height, title, 0, 0);
        if (handle == 0) {
            glfwTerminate();
            errors.free();
            throw new IllegalStateException("cannot create an OpenGL window (is Mesa installed? apt-get install libgl1-mesa-dri)");
        }
        glfwMakeContextCurrent(handle);
        GL.createCapabilities();
    }

    /** The drawable size in pixels (it may differ from the window size on high-density screens). */
    int[] framebufferSize() {
        int[] w = new int[1], h = new int[1];
        glfwGetFramebufferSize(handle, w, h);
        return new int[] {w[0], h[0]};
    }

    @Override
    public void close() {
        glfwDestroyWindow(handle);
        glfwTerminate();
        errors.free();
    }
}
