package handsim.report;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.time.Instant;
import java.time.LocalDateTime;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.function.Consumer;

/**
 * One writer per folder: a run folder, a study folder or an evaluation's results are held by one
 * process at a time through an operating-system file lock ({@link FileChannel#tryLock}) on a
 * lock file, {@code DIR/.handsim.lock} for a folder and {@code .NAME.handsim.lock} beside a file.
 * The lock file says who holds it (process id, command line, start time), so a second process is
 * refused at once with one line naming the holder ({@link Held}, an {@link
 * IllegalArgumentException}: exit status 2).
 *
 * <p>The lock file is never opened again while held (on POSIX systems closing any descriptor of a
 * file drops the process's locks on it). The system releases the lock when its process ends,
 * however it ends; a holder that ended
 * normally also deletes the file. So a lock file that can be locked but still names a process
 * was left by one that was killed: it is taken over, and the takeover is said. Within one process
 * holding is re-entrant (a command and the study it opens hold the same folder). Everything held
 * is released by {@link #releaseAll} (the end of a command) and when the JVM exits.
 */
public final class Locks {

    /** A lock another live process holds. */
    public static final class Held extends IllegalArgumentException {
        private static final long serialVersionUID = 1L;

        Held(String message) {
            super(message);
        }
    }

    /** The name of a folder's lock file. */
    public static final String FOLDER_LOCK = ".handsim.lock";
    private static final String FILE_LOCK_SUFFIX = ".handsim.lock";
    private static final DateTimeFormatter WHEN = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss");

    /** What this process says about itself in its lock files: its command line (set by the launcher's entry point). */
    private static volatile String command = ProcessHandle.current().info().commandLine().orElse("java");
    private static final Map<Path, Holding> HELD = new LinkedHashMap<>();

    private record Holding(FileChannel channel, FileLock lock) {
    }

    static {
        Runtime.getRuntime().addShutdownHook(new Thread(Locks::releaseAll, "handsim-locks"));
    }

    private Locks() {
    }

    /** The command line this process names itself by in its lock files, e.g. {@code scripts/handsim demo --out D}. */
    public static void describeProcess(String commandLine) {
        command = Objects.requireNonNull(commandLine);
    }

    /** Whether {@code name} is a lock file's name. */
    public static boolean isLockFile(String name) {
        return name.equals(FOLDER_LOCK) || name.startsWith(".") && name.endsWith(FILE_LOCK_SUFFIX);
    }

    /**
     * Holds the folder {@code dir} (which must exist) for this process. {@code label} names it in
     * messages ({@code "--out /x/run"}); {@code notes} hears of a takeover from a process that
     * ended without releasing it.
     *
     * @throws Held when another live process holds it
     */
    public static void holdFolder(Path dir, String label, Consumer<String> notes) {
        hold(dir.toAbsolutePath().normalize().resolve(FOLDER_LOCK), label, notes);
    }

    /** Holds the file {@code file} (which need not exist) for this process: the lock file beside it. */
    public static void holdFile(Path file, String label, Consumer<String> notes) {
        Path abs = file.toAbsolutePath().normalize();
        hold(abs.resolveSibling("." + abs.getFileName() + FILE_LOCK_SUFFIX), label, notes);
    }

    private static synchronized void hold(Path lockFile, String label, Consumer<String> notes) {
        if (HELD.containsKey(lockFile)) {
            return;
        }
        for (int attempt = 0; ; attempt++) {
            FileChannel channel = null;
            try {
                Object before = fileKey(lockFile);
                channel = FileChannel.open(lockFile, StandardOpenOption.CREATE, StandardOpenOption.READ, StandardOpenOption.WRITE);
                Object opened = fileKey(lockFile);
                FileLock lock;
                try {
                    lock = channel.tryLock();
                } catch (OverlappingFileLockException sameProcess) {
                    lock = null;
                }
                if (lock == null) {
                    String text = read(channel);
                    if (text.isBlank()) { // the holder is between creating the file and writing who it is
                        sleepQuietly(100);
                        text = read(channel);
                    }
                    channel.close();
                    throw new Held(label + " is in use by another handsim process (" + describeHolder(text) + "): wait for it "
                            + "to end, or give another one");
                }
                if (opened == null || !opened.equals(fileKey(lockFile)) || before != null && !before.equals(opened)) {
                    // a holder deleted it (releasing) while we opened and locked it: lock the file there now. Its
                    // identity is compared by stat alone: opening the file again and closing it would drop the lock
                    lock.release();
                    channel.close();
                    if (attempt < 10) {
                        continue;
                    }
                    throw new Held(label + ": its lock file " + lockFile + " keeps changing (other processes starting?)");
                }
                String previous = read(channel);
                channel.truncate(0);
                channel.write(ByteBuffer.wrap(record().getBytes(StandardCharsets.UTF_8)), 0);
                channel.force(true);
                if (!previous.isBlank()) {
                    notes.accept(label + " was held by " + describeHolder(previous) + ", which ended without releasing it: "
                            + "taking it over");
                }
                HELD.put(lockFile, new Holding(channel, lock));
                return;
            } catch (IOException e) {
                closeQuietly(channel);
                throw new IllegalArgumentException(label + ": cannot lock it (" + lockFile + ": "
                        + (e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName()) + ")");
            } catch (RuntimeException e) {
                closeQuietly(channel);
                throw e;
            }
        }
    }

    /** The file system's identity of the file at {@code path} (its inode), from its attributes alone; null when there is none. */
    private static Object fileKey(Path path) {
        try {
            Object key = Files.readAttributes(path, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS).fileKey();
            return key != null ? key : path; // a system without file keys: a rare race is not guarded against there
        } catch (IOException e) {
            return null;
        }
    }

    /** Releases what this process holds under {@code dir} or of {@code file} ({@link #holdFolder}, {@link #holdFile}). */
    public static synchronized void release(Path dirOrFile) {
        Path abs = dirOrFile.toAbsolutePath().normalize();
        for (Path lockFile : new java.util.ArrayList<>(HELD.keySet())) {
            if (lockFile.equals(abs.resolve(FOLDER_LOCK)) || lockFile.equals(abs.resolveSibling("." + abs.getFileName() + FILE_LOCK_SUFFIX))) {
                release(lockFile, HELD.remove(lockFile));
            }
        }
    }

    /** Releases everything this process holds, deleting the lock files. */
    public static synchronized void releaseAll() {
        HELD.forEach(Locks::release);
        HELD.clear();
    }

    /** Deletes the lock file while still holding it (so nobody locks a file about to vanish), then lets go. */
    private static void release(Path lockFile, Holding h) {
        try {
            Files.deleteIfExists(lockFile);
        } catch (IOException e) {
            // the lock is released below all the same; the next holder takes the file over
        }
        try {
            h.lock().release();
        } catch (IOException | RuntimeException e) {
            // closing the channel releases it too
        }
        closeQuietly(h.channel());
    }

    /** What a lock file says: {@code pid N}, the command and the start time, on lines of {@code key: value}. */
    private static String record() {
        ProcessHandle me = ProcessHandle.current();
        Instant started = me.info().startInstant().orElse(Instant.now());
        return "pid: " + me.pid() + "\ncommand: " + command.replace('\n', ' ') + "\nstarted: "
                + WHEN.format(LocalDateTime.ofInstant(started, ZoneId.systemDefault())) + "\n";
    }

    /** {@code pid 123, scripts/handsim demo ..., started yyyy-MM-dd HH:mm:ss} from a lock file's text. */
    private static String describeHolder(String text) {
        Map<String, String> fields = new LinkedHashMap<>();
        text.lines().forEach(line -> {
            int colon = line.indexOf(": ");
            if (colon > 0) {
                fields.put(line.substring(0, colon), line.substring(colon + 2));
            }
        });
        return "pid " + fields.getOrDefault("pid", "unknown") + ", " + fields.getOrDefault("command", "an unknown command")
                + ", started " + fields.getOrDefault("started", "at an unknown time");
    }

    private static String read(FileChannel channel) throws IOException {
        long size = Math.min(channel.size(), 1 << 16);
        ByteBuffer buffer = ByteBuffer.allocate((int) size);
        channel.read(buffer, 0);
        return new String(buffer.array(), 0, buffer.position(), StandardCharsets.UTF_8);
    }

    private static void sleepQuietly(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static void closeQuietly(FileChannel channel) {
        if (channel != null) {
            try {
                channel.close();
            } catch (IOException e) {
                // nothing more to do
            }
        }
    }
}
