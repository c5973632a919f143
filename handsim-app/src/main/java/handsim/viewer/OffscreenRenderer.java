package handsim.viewer;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL30.*;

import handsim.sim.WorldSnapshot;
import java.awt.image.BufferedImage;
import java.nio.ByteBuffer;
import java.util.function.Consumer;
import org.lwjgl.BufferUtils;

/**
 * Renders snapshots into an off-screen framebuffer of a hidden GLFW window and reads them back
 * as images: {@code render} and the tests use it; frames go to PNG files through {@link
 * FrameFolder}, as the viewer's recording does. Needs an X display (under {@code xvfb-run} on a machine without one).
 */
public final class OffscreenRenderer implements AutoCloseable {

    private final int width;
    private final int height;
    private final GlWindow window;
    private final int framebuffer;
    private final int colorBuffer;
    private final int depthBuffer;
    private final SceneRenderer scene;
    private final ByteBuffer pixels;

    public OffscreenRenderer(int width, int height, ViewerConfig config) {
        if (width < 16 || height < 16 || width > 8192 || height > 8192) {
            throw new IllegalArgumentException("image size must be within 16..8192 pixels, got " + width + "x" + height);
        }
        this.width = width;
        this.height = height;
        window = new GlWindow(64, 64, "handsim offscreen", false);
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
        scene = new SceneRenderer(config);
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

    /** Draws deforming surfaces (a card scene) as {@code camera} sees them and returns the image. */
    public BufferedImage renderSurfaces(java.util.List<SurfaceMesh> surfaces, Camera camera) {
        scene.begin(camera, width, height);
        scene.drawSurfaces(surfaces);
        glFinish();
        return readImage(width, height, pixels);
    }

    /** The current read framebuffer as an image. */
    static BufferedImage readImage(int width, int height, ByteBuffer pixels) {
        return FrameFolder.toImage(width, height, readPixels(width, height, pixels));
    }

    /** The current read framebuffer's RGBA bytes, rows bottom-up; {@code buffer} holds width x height x 4 bytes. */
    static byte[] readPixels(int width, int height, ByteBuffer buffer) {
        buffer.clear();
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, buffer);
        byte[] rgba = new byte[width * height * 4];
        buffer.get(rgba);
        return rgba;
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
        window.close();
    }
}
