package handsim.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * One process per folder: another process holding it is named and refused at once; a holder
 * killed with SIGKILL is taken over, and the takeover is said; a clean release leaves nothing.
 */
@Tag("fast")
class LocksTest {

    @TempDir
    Path tmp;

    @Test
    void aFolderAnotherProcessHoldsIsRefusedNamingItAndTakenOverOnceThatProcessIsKilled() throws Exception {
        Path dir = Files.createDirectories(tmp.resolve("run"));
        Process holder = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), LockHolder.class.getName(), dir.toString()).redirectErrorStream(true).start();
        try {
            BufferedReader out = new BufferedReader(new InputStreamReader(holder.getInputStream(), StandardCharsets.UTF_8));
            assertEquals("held", out.readLine(), "the other process holds the folder");

            long t0 = System.nanoTime();
            Locks.Held refused = assertThrows(Locks.Held.class, () -> Locks.holdFolder(dir, "--out " + dir, n -> { }));
            double seconds = (System.nanoTime() - t0) * 1e-9;
            assertTrue(seconds < 0.5, "refused at once, not after waiting: " + seconds + " s");
            assertTrue(refused.getMessage().startsWith("--out " + dir + " is in use by another handsim process (pid " + holder.pid()
                    + ", LockHolder " + dir + ", started "), refused.getMessage());

            holder.destroyForcibly(); // SIGKILL: no exit hooks, the lock file stays with its holder's name
            assertTrue(holder.waitFor(30, TimeUnit.SECONDS));
            assertTrue(Files.exists(dir.resolve(Locks.FOLDER_LOCK)));
            List<String> notes = new ArrayList<>();
            Locks.holdFolder(dir, "--out " + dir, notes::add);
            assertEquals(1, notes.size(), "the takeover is said");
            assertTrue(notes.get(0).contains("was held by pid " + holder.pid()) && notes.get(0).endsWith("taking it over"), notes.get(0));
            Locks.holdFolder(dir, "--out " + dir, notes::add);
            assertEquals(1, notes.size(), "holding it again in the same process is a no-op");
        } finally {
            holder.destroyForcibly();
            Locks.releaseAll();
        }
        assertFalse(Files.exists(dir.resolve(Locks.FOLDER_LOCK)), "a release leaves no lock file");
    }

    @Test
    void aFileIsHeldThroughALockFileBesideIt() {
        Path json = tmp.resolve("F.json");
        try {
            Locks.holdFile(json, "--json " + json, n -> { });
            assertTrue(Files.exists(tmp.resolve(".F.json.handsim.lock")));
            assertTrue(Locks.isLockFile(".F.json.handsim.lock") && Locks.isLockFile(Locks.FOLDER_LOCK) && !Locks.isLockFile("F.json"));
        } finally {
            Locks.release(json);
        }
        assertFalse(Files.exists(tmp.resolve(".F.json.handsim.lock")));
    }
}
