package handsim.app;

import handsim.config.ReadLog;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/**
 * Files that travelled to a cluster's executor as bytes (policies), kept there under their
 * SHA-256 in the JVM's temporary folder, so that code that reads a policy from a path reads the
 * driver's bytes; written whole before they are named, once per executor.
 */
final class CachedFiles {

    private CachedFiles() {
    }

    /** A file of this JVM's cache holding {@code bytes}. */
    static Path of(byte[] bytes) {
        Path dir = Path.of(System.getProperty("java.io.tmpdir"), "handsim-policies");
        Path file = dir.resolve(ReadLog.sha256(bytes) + ".json");
        try {
            if (!Files.exists(file)) {
                Files.createDirectories(dir);
                Path tmp = Files.createTempFile(dir, "policy", ".tmp");
                Files.write(tmp, bytes);
                Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot keep a policy in " + dir, e);
        }
        return file;
    }
}
