package handsim.report;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.NullNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import java.awt.image.RenderedImage;
import java.io.BufferedOutputStream;
import java.io.FileOutputStream;
import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.Iterator;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;

/**
 * Writing result files so that a reader, or a run killed at any moment, only ever sees the old
 * or the new complete file: the content goes to a temporary file beside the target,
 * {@code .NAME.handsim-PID-N.tmp}, which is forced to disk and then moved over the target
 * atomically.
 *
 * <p>Files are created with the ordinary mode, 0666 less the umask (0644 under the usual umask
 * 022), and folders with 0777 less the umask (0755). A temporary file never outlives its write:
 * it is deleted when the write fails, when the JVM exits (a normal end, an error, Ctrl-C or a
 * plain {@code kill}), and, when a {@code kill -9} left one behind, by the first write of a later
 * run into its folder (it names the process that wrote it, and that process has ended).
 */
public final class Outputs {

    /** Writes the content of a file to a stream (which it need not close). */
    @FunctionalInterface
    public interface Writer {
        void write(OutputStream out) throws IOException;
    }

    private static final long PID = ProcessHandle.current().pid();
    private static final String MARK = ".handsim-";
    /** {@code .NAME.handsim-PID-N.tmp}: group 1 is the writing process. */
    private static final Pattern TEMPORARY = Pattern.compile("^\\..*\\.handsim-(\\d+)-\\d+\\.tmp$");
    private static final AtomicLong COUNTER = new AtomicLong();
    private static final Set<Path> IN_FLIGHT = ConcurrentHashMap.newKeySet();
    /** Folders already cleared of temporary files left by killed processes. */
    private static final Set<Path> SWEPT = ConcurrentHashMap.newKeySet();

    static {
        java.lang.Runtime.getRuntime().addShutdownHook(new Thread(() -> IN_FLIGHT.forEach(Outputs::deleteQuietly),
                "handsim-temporary-files"));
    }

    private Outputs() {
    }

    /**
     * Writes {@code file} atomically with the bytes {@code writer} produces; creates its folder if
     * needed. The bytes go to a temporary file of a name no other write uses (this process's id
     * and a counter), which is forced to disk and renamed over the target; the folder is then
     * forced too, so the rename itself survives a power cut. Plain streams, not NIO channels:
     * an interrupt of the writing thread does not break the write off. A failure (a full disk, a
     * folder that cannot be written) deletes the temporary file and is a {@link
     * FileSystemException} naming the target and the reason.
     */
    public static void write(Path file, Writer writer) throws IOException {
        Path abs = file.toAbsolutePath();
        Path dir = abs.getParent();
        Path tmp = temporary(abs);
        IN_FLIGHT.add(tmp);
        try {
            Files.createDirectories(dir);
            sweepOnce(dir);
            Files.createFile(tmp);
            try (FileOutputStream stream = new FileOutputStream(tmp.toFile())) {
                OutputStream out = new BufferedOutputStream(stream, 1 << 16);
                writer.write(new FilterOutputStream(out) {
                    @Override
                    public void write(byte[] b, int off, int len) throws IOException {
                        out.write(b, off, len);
                    }

                    @Override
                    public void close() throws IOException {
                        out.flush(); // the file stays open until forced to disk
                    }
                });
                out.flush();
                stream.getFD().sync();
            }
            Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            syncFolder(dir);
        } catch (IOException e) {
            throw failed(abs, e);
        } finally {
            deleteQuietly(tmp);
            IN_FLIGHT.remove(tmp);
        }
    }

    /**
     * Appends {@code bytes} to {@code file} (created if missing) and forces them to disk before
     * returning: a journal's line, a metrics row. The one kind of write that is not atomic, so
     * its readers drop a partial last line (what a kill during an append leaves).
     */
    public static void append(Path file, byte[] bytes) throws IOException {
        Path abs = file.toAbsolutePath();
        try (FileOutputStream out = new FileOutputStream(abs.toFile(), true)) {
            out.write(bytes);
            out.getFD().sync();
        } catch (IOException e) {
            throw failed(abs, e);
        }
    }

    /** Writes a copy of {@code from} as {@code to}, atomically. */
    public static void copy(Path from, Path to) throws IOException {
        write(to, out -> Files.copy(from, out));
    }

    /**
     * JSON with every number that is not finite written as {@code null} (JSON has no NaN or
     * infinity: a figure that could not be measured, such as a mean over no throws, is null).
     */
    public static void writeJson(Path file, JsonNode node) throws IOException {
        writeString(file, Json.pretty(finiteOrNull(node.deepCopy())) + "\n");
    }

    public static void writeString(Path file, String text) throws IOException {
        write(file, out -> out.write(text.getBytes(StandardCharsets.UTF_8)));
    }

    /** A PNG, encoded in memory (ImageIO's disk cache would be one more temporary file). */
    public static void writePng(Path file, RenderedImage image) throws IOException {
        ImageIO.setUseCache(false);
        write(file, out -> {
            if (!ImageIO.write(image, "png", out)) {
                throw new IOException("no PNG encoder for " + file);
            }
        });
    }

    /**
     * Makes {@code previous} a copy of {@code file} (a hard link where the file system has them),
     * atomically: {@code previous} is always either its old or its new complete content.
     */
    public static void keepCopy(Path file, Path previous) throws IOException {
        Path abs = previous.toAbsolutePath();
        Path tmp = temporary(abs);
        IN_FLIGHT.add(tmp);
        try {
            try {
                Files.createLink(tmp, file);
            } catch (UnsupportedOperationException | FileSystemException noLinks) {
                Files.deleteIfExists(tmp);
                Files.copy(file, tmp);
            }
            Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            syncFolder(abs.getParent());
        } catch (IOException e) {
            throw failed(abs, e);
        } finally {
            deleteQuietly(tmp);
            IN_FLIGHT.remove(tmp);
        }
    }

    /** Deletes the temporary files in {@code dir} whose writing process has ended; returns how many. */
    public static int sweep(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) {
            return 0;
        }
        int deleted = 0;
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir, ".*" + MARK + "*.tmp")) {
            for (Path f : files) {
                Matcher m = TEMPORARY.matcher(f.getFileName().toString());
                if (m.matches() && !alive(Long.parseLong(m.group(1)))) {
                    deleted += Files.deleteIfExists(f) ? 1 : 0;
                }
            }
        }
        return deleted;
    }

    /** Whether {@code name} is one of the temporary files this class writes. */
    public static boolean isTemporary(String name) {
        return TEMPORARY.matcher(name).matches();
    }

    private static boolean alive(long pid) {
        return pid == PID || ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false);
    }

    private static void sweepOnce(Path dir) throws IOException {
        if (SWEPT.add(dir)) {
            sweep(dir);
        }
    }

    private static Path temporary(Path target) {
        return target.resolveSibling("." + target.getFileName() + MARK + PID + "-" + COUNTER.incrementAndGet() + ".tmp");
    }

    /**
     * Forces a folder's entries to disk (where the system allows a folder to be opened for it),
     * so that a file just renamed into it is there after a crash.
     */
    private static void syncFolder(Path dir) {
        try (FileChannel channel = FileChannel.open(dir, StandardOpenOption.READ)) {
            channel.force(true);
        } catch (IOException | RuntimeException e) {
            // some systems cannot open a folder for this: the file itself is on disk already
        }
    }

    /** A failed write as one that names its target and says why in a few words (Java's messages are often just a path). */
    private static FileSystemException failed(Path target, IOException e) {
        if (e instanceof FileSystemException f && target.toString().equals(f.getFile())) {
            return f;
        }
        String reason = e instanceof java.nio.file.AccessDeniedException ? "permission denied"
                : e instanceof java.nio.file.NoSuchFileException ? "no such folder"
                : e instanceof FileSystemException f && f.getReason() != null ? f.getReason()
                : e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
        FileSystemException named = new FileSystemException(target.toString(), null, "cannot write it: " + reason);
        named.initCause(e);
        return named;
    }

    private static void deleteQuietly(Path p) {
        try {
            Files.deleteIfExists(p);
        } catch (IOException e) {
            // the JVM is exiting: nothing more can be done about it
        }
    }

    /** Replaces the non-finite numbers in a tree by null, in place; returns the tree. */
    private static JsonNode finiteOrNull(JsonNode node) {
        if (node instanceof ObjectNode o) {
            for (Iterator<Map.Entry<String, JsonNode>> it = o.fields(); it.hasNext(); ) {
                Map.Entry<String, JsonNode> e = it.next();
                e.setValue(finiteOrNull(e.getValue()));
            }
        } else if (node instanceof ArrayNode a) {
            for (int i = 0; i < a.size(); i++) {
                a.set(i, finiteOrNull(a.get(i)));
            }
        } else if (node.isFloatingPointNumber() && !Double.isFinite(node.asDouble())) {
            return NullNode.getInstance();
        }
        return node;
    }
}
