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
    /** GLFW's last error, for the message of a window that cannot be opened. */
    private String lastError = "";
    /** While the window opens, an error is said once, by the exception that follows it. */
    private boolean opening = true;

    /** Opens the window; without a usable display fails with one line ({@link IllegalArgumentException}) saying what to do. */
    GlWindow(int width, int height, String title, boolean visible) {
        errors = GLFWErrorCallback.create((code, description) -> {
            lastError = GLFWErrorCallback.getDescription(description);
            if (!opening) {
                System.err.println("handsim: GLFW: " + lastError);
            }
        });
        errors.set();
        if (System.getenv("WAYLAND_DISPLAY") == null) {
            // X11 only: GLFW would otherwise probe for Wayland first and complain about it
            glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_X11);
        }
        if (!glfwInit()) {
            errors.free();
            throw new IllegalArgumentException("cannot open the X display (DISPLAY=" + System.getenv("DISPLAY") + "; " + lastError
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
            throw new IllegalArgumentException("cannot create an OpenGL window (" + lastError
                    + "; is Mesa installed? apt-get install libgl1-mesa-dri)");
        }
        glfwMakeContextCurrent(handle);
        GL.createCapabilities();
        opening = false;
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
