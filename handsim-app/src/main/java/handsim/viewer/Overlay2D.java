package handsim.viewer;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL12.GL_BGRA;
import static org.lwjgl.opengl.GL12.GL_UNSIGNED_INT_8_8_8_8_REV;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.nio.IntBuffer;
import org.lwjgl.BufferUtils;

/**
 * A flat picture drawn over the 3D view: a Java2D image (text and panels of the heads-up
 * display) kept in a texture and drawn as one quad at screen pixels. Re-uploading the picture
 * costs a texture copy, so its owner updates it only when its content changes (and the status
 * panel at most a few times a second); drawing it each frame is one blended quad, far cheaper
 * on a software renderer than a quad per character.
 */
final class Overlay2D implements AutoCloseable {

    private final int texture = glGenTextures();
    private int textureWidth;
    private int textureHeight;
    private int width;
    private int height;
    private IntBuffer upload = BufferUtils.createIntBuffer(1);

    /** Replaces the picture (TYPE_INT_ARGB, not premultiplied). */
    void set(BufferedImage image) {
        width = image.getWidth();
        height = image.getHeight();
        int[] argb = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
        if (upload.capacity() < argb.length) {
            upload = BufferUtils.createIntBuffer(argb.length);
        }
        upload.clear();
        upload.put(argb, 0, width * height).flip();
        glBindTexture(GL_TEXTURE_2D, texture);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        if (width > textureWidth || height > textureHeight) {
            textureWidth = Math.max(width, textureWidth);
            textureHeight = Math.max(height, textureHeight);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, textureWidth, textureHeight, 0, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV,
                    (IntBuffer) null);
        }
        // Java's ARGB ints are BGRA bytes in little-endian memory: upload as they are
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, upload);
        glBindTexture(GL_TEXTURE_2D, 0);
    }

    int width() {
        return width;
    }

    int height() {
        return height;
    }

    /** Draws the picture with its top-left corner at pixel (x, y); needs {@link #begin} first. */
    void draw(int x, int y) {
        if (width == 0) {
            return;
        }
        float u = (float) width / textureWidth, v = (float) height / textureHeight;
        glEnable(GL_TEXTURE_2D);
        glBindTexture(GL_TEXTURE_2D, texture);
        glColor4f(1, 1, 1, 1);
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0);
        glVertex2i(x, y);
        glTexCoord2f(0, v);
        glVertex2i(x, y + height);
        glTexCoord2f(u, v);
        glVertex2i(x + width, y + height);
        glTexCoord2f(u, 0);
        glVertex2i(x + width, y);
        glEnd();
        glBindTexture(GL_TEXTURE_2D, 0);
        glDisable(GL_TEXTURE_2D);
    }

    /** Screen pixels, y down from the top-left corner of a {@code width} x {@code height} framebuffer; blending on. */
    static void begin(int width, int height) {
        glViewport(0, 0, width, height);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(0, width, height, 0, -1, 1);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_LIGHTING);
        glDisable(GL_CULL_FACE);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }

    static void end() {
        glDisable(GL_BLEND);
        glEnable(GL_DEPTH_TEST);
    }

    @Override
    public void close() {
        glDeleteTextures(texture);
    }
}
