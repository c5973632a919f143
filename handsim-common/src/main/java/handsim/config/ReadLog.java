package handsim.config;

import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.Map;
import java.util.SortedMap;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Every JSON file this process has read ({@link Json#load}): the model, the configs, policies,
 * goal lists, each with the SHA-256 of its bytes as read. A result records them as its
 * provenance, so a figure names the exact inputs it came from.
 */
public final class ReadLog {

    private static final Map<Path, String> READ = new ConcurrentHashMap<>();

    private ReadLog() {
    }

    /** Notes that {@code file} was read with these bytes. */
    static void record(Path file, byte[] bytes) {
        READ.put(file.toAbsolutePath().normalize(), sha256(bytes));
    }

    /** The files read so far, by path (relative to the project root when inside it), with their SHA-256. */
    public static SortedMap<String, String> files() {
        Path root = Home.root();
        SortedMap<String, String> out = new TreeMap<>();
        READ.forEach((file, hash) -> out.put(file.startsWith(root) ? root.relativize(file).toString() : file.toString(), hash));
        return out;
    }

    /** The SHA-256 of {@code bytes}, in hex. */
    public static String sha256(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java runtime has SHA-256", e);
        }
    }
}
