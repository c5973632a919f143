package handsim.viewer;

import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL30.*;

import handsim.sim.WorldSnapshot;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.function.Consumer;
import javax.imageio.ImageIO;
import org.lwjgl.BufferUtils;
import org.lwjgl.glfw.GLFWErrorCallback;
import org.lwjgl.opengl.GL;

/**
 * Renders snapshots into an off-screen framebuffer of a hidden GLFW window and reads them back
 * as images: {@code render} and the tests use it, and the viewer's recording writes the same
 * PNGs. Needs an X display (under {@code xvfb-run} on a machine without one).
 */
public final class OffscreenRenderer implements AutoCloseable {

    private final int width;
    private final int height;
    private final long window;
    private final int framebuffer;
    private final int colorBuffer;
    private final int depthBuffer;
    private final SceneRenderer scene;
    private final ByteBuffer pixels;
    private final GLFWErrorCallback errors;

    public OffscreenRenderer(int width, int height) {
        if (width < 16 || height < 16 || width > 8192 || height > 8192) {
            throw new IllegalArgumentException("image size must be within 16..8192 pixels, got " + width + "x" + height);
        }
        this.width = width;
        this.height = height;
        errors = GLFWErrorCallback.createPrint(System.err).set();
        if (!glfwInit()) {
            errors.free();
            throw new IllegalStateException("cannot open the X display (DISPLAY=" + System.getenv("DISPLAY")
                    + "): run under xvfb-run (apt-get install xvfb xauth libgl1-mesa-dri)");
        }
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
        window = glfwCreateWindow(64, 64, "handsim offscreen", 0, 0);
        if (window == 0) {
            glfwTerminate();
            errors.free();
            throw new IllegalStateException("cannot create an OpenGL context (is Mesa installed? apt-get install libgl1-mesa-dri)");
        }
        glfwMakeContextCurrent(window);
        GL.createCapabilities();
        framebuffer = glGenFramebuffers();
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        colorBuffer = glGenRenderbuffers();
        glBindRenderbuffer(GL_RENDERBUFFER, colorBuffer);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colorBuffer);
        depthBuffer = glGenRenderbuffers();
        glBindRenderbuffer(GL_RENDERBUFFER, depthBuffer);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depthBuffer);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            throw new IllegalStateException("off-screen framebuffer incomplete");
        }
        scene = new SceneRenderer();
        pixels = BufferUtils.createByteBuffer(width * height * 4);
    }

    /** Draws the world as {@code camera} sees it, then {@code extras} (goals, overlays), and returns the image. */
    public BufferedImage render(WorldSnapshot snapshot, Camera camera, Consumer<SceneRenderer> extras) {
        scene.begin(camera, width, height);
        scene.drawWorld(snapshot);
        if (extras != null) {
            extras.accept(scene);
        }
        glFinish();
        return readImage(width, height, pixels);
    }

    /** The current read framebuffer as an image (OpenGL's rows run bottom-up). */
    static BufferedImage readImage(int width, int height, ByteBuffer pixels) {
        pixels.clear();
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            int row = (height - 1 - y) * width * 4;
            for (int x = 0; x < width; x++) {
                int i = row + 4 * x;
                img.setRGB(x, y, (pixels.get(i) & 0xff) << 16 | (pixels.get(i + 1) & 0xff) << 8 | (pixels.get(i + 2) & 0xff));
            }
        }
        return img;
    }

    /** Writes a PNG atomically: a temporary file in the same folder, moved into place. */
    public static void writePng(BufferedImage image, Path file) throws IOException {
        Path dir = file.toAbsolutePath().getParent();
        Files.createDirectories(dir);
        Path tmp = Files.createTempFile(dir, ".frame", ".png");
        ImageIO.write(image, "png", tmp.toFile());
        Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    @Override
    public void close() {
        scene.close();
        glDeleteRenderbuffers(colorBuffer);
        glDeleteRenderbuffers(depthBuffer);
        glDeleteFramebuffers(framebuffer);
        glfwDestroyWindow(window);
        glfwTerminate();
        errors.free();
    }
}
