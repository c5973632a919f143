package handsim.viewer;

import handsim.report.Outputs;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;

/**
 * Numbered PNG frames {@code 00000.png, 00001.png, ...} in one folder, which
 * {@code ffmpeg -framerate F -i DIR/%05d.png} turns into a video. {@code render} and the viewer's
 * recording both write through it. Images are converted and encoded on a background thread so
 * that drawing need not wait; when {@link #QUEUE} frames are waiting, the caller encodes the
 * next one itself (recording then slows drawing rather than growing memory without bound).
 */
public final class FrameFolder implements AutoCloseable {

    static final int QUEUE = 8;

    private final Path dir;
    private final ThreadPoolExecutor writer;
    private final java.util.List<Future<?>> pending = new java.util.ArrayList<>();
    private int count;

    public FrameFolder(Path dir) throws IOException {
        this.dir = dir;
        Files.createDirectories(dir);
        writer = new ThreadPoolExecutor(1, 1, 0, TimeUnit.SECONDS, new ArrayBlockingQueue<>(QUEUE), r -> {
            Thread t = new Thread(r, "handsim-png");
            t.setDaemon(true);
            return t;
        }, new ThreadPoolExecutor.CallerRunsPolicy());
    }

    /** Queues the next frame; {@code image} is called on the writer thread. Returns the file it will be. */
    public Path add(Supplier<BufferedImage> image) {
        Path file = dir.resolve(String.format("%05d.png", count++));
        pending.removeIf(Future::isDone);
        pending.add(writer.submit(() -> {
            try {
                writePng(image.get(), file);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }));
        return file;
    }

    /** Frames added so far. */
    public int count() {
        return count;
    }

    public Path dir() {
        return dir;
    }

    /** Waits for every frame to be written; fails if one could not be. */
    @Override
    public void close() throws IOException {
        writer.shutdown();
        try {
            for (Future<?> f : pending) {
                f.get();
            }
        } catch (ExecutionException e) {
            throw new IOException("writing a frame into " + dir + " failed: " + e.getCause().getMessage(), e.getCause());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while writing frames into " + dir, e);
        }
    }

    /** Writes a PNG atomically ({@link Outputs}). */
    public static void writePng(BufferedImage image, Path file) throws IOException {
        Outputs.writePng(file, image);
    }

    /** An image from OpenGL's RGBA pixels (rows bottom-up, as glReadPixels returns them). */
    public static BufferedImage toImage(int width, int height, byte[] rgba) {
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        int[] out = ((DataBufferInt) img.getRaster().getDataBuffer()).getData();
        for (int y = 0; y < height; y++) {
            int row = (height - 1 - y) * width * 4, o = y * width;
            for (int x = 0; x < width; x++) {
                int i = row + 4 * x;
                out[o + x] = (rgba[i] & 0xff) << 16 | (rgba[i + 1] & 0xff) << 8 | (rgba[i + 2] & 0xff);
            }
        }
        return img;
    }
}
