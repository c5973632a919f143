package handsim.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The one writer: a write that fails part-way (a full disk) keeps the old file, leaves no
 * temporary file and names the file it was writing; appends add to the end.
 */
@Tag("fast")
class OutputsTest {

    @TempDir
    Path tmp;

    /**
     * A real full disk where a 32 kB tmpfs can be mounted (as root), else the failure a full disk
     * gives a writer, injected: "No space left on device" from the stream.
     */
    @Test
    void aWriteThatRunsOutOfSpaceKeepsTheOldFileLeavesNothingAndNamesTheFile() throws Exception {
        Path disk = tmp.resolve("disk");
        Files.createDirectories(disk);
        boolean mounted = mountTmpfs(disk, "32k");
        try {
            Path file = disk.resolve("trajectory.json");
            Outputs.writeString(file, "the old content");
            byte[] big = new byte[1 << 20];
            FileSystemException e = assertThrows(FileSystemException.class, () -> Outputs.write(file, out -> {
                if (!mounted) {
                    out.write(big, 0, 1000);
                    throw new IOException("No space left on device");
                }
                out.write(big); // 1 MB into 32 kB
            }));
            assertEquals(file.toAbsolutePath() + ": cannot write it: No space left on device", e.getMessage());
            assertEquals("the old content", Files.readString(file), "the old file is whole");
            try (Stream<Path> files = Files.list(disk)) {
                assertEquals(List.of(file), files.toList(), "no temporary file left");
            }
        } finally {
            if (mounted) {
                new ProcessBuilder("umount", disk.toString()).inheritIO().start().waitFor(10, TimeUnit.SECONDS);
            }
        }
    }

    @Test
    void anAppendAddsToTheEndAndCreatesTheFile() throws IOException {
        Path f = tmp.resolve("metrics.csv");
        Outputs.append(f, "a\n".getBytes(StandardCharsets.UTF_8));
        Outputs.append(f, "b\n".getBytes(StandardCharsets.UTF_8));
        assertEquals("a\nb\n", Files.readString(f));
        FileSystemException e = assertThrows(FileSystemException.class, () -> Outputs.append(tmp.resolve("none/x.csv"), new byte[1]));
        assertTrue(e.getMessage().startsWith(tmp.resolve("none/x.csv") + ": cannot write it: "), e.getMessage());
    }

    /** Mounts a tmpfs of {@code size} on {@code dir}; false where that is not allowed (not root, no mount). */
    static boolean mountTmpfs(Path dir, String size) throws InterruptedException {
        try {
            Process p = new ProcessBuilder("mount", "-t", "tmpfs", "-o", "size=" + size, "tmpfs", dir.toString())
                    .redirectErrorStream(true).start();
            p.getInputStream().readAllBytes();
            return p.waitFor(10, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException noMount) {
            return false;
        }
    }
}
