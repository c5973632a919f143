package handsim.app;

import handsim.config.Home;
import handsim.report.Locks;
import java.io.IOException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.stream.Stream;

/**
 * Run folders of demo, train and warmstart: {@code KIND__NAME__SEED__yyyyMMdd-HHmmss}, under
 * runs/ unless told otherwise. A run claims its folder by creating it (an atomic create that
 * fails if the folder exists), so two runs started in the same second never share one: the
 * second gets the name with {@code -2} (then {@code -3}, ...) appended. A run holds its folder
 * ({@link Locks}) while it runs: {@code train --resume} of a folder in use is refused.
 */
final class RunFolders {

    private static final DateTimeFormatter START_TIME = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss");
    /** What a run's name may hold: it becomes part of a folder name. */
    private static final String NAME = "[A-Za-z0-9][A-Za-z0-9._-]*";

    private RunFolders() {
    }

    /**
     * A new run's folder, named by what it is and when it started, created in {@code base}
     * ({@code option}'s value; null: the project's runs/), and held by this process alone
     * ({@link Locks}) until the command ends.
     */
    static Path claim(Path base, String option, String kind, String name, long seed) {
        if (!name.matches(NAME) || name.length() > 100) {
            throw new IllegalArgumentException("a run's name becomes its folder's name: letters, digits, '.', '_' and '-' "
                    + "(at most 100, not starting with '.' or '-'), got \"" + name + "\"");
        }
        Path dir = base != null ? base : Home.resolve("runs");
        new OutputPaths().folder(option, dir).check();
        String stem = kind + "__" + name + "__" + seed + "__" + LocalDateTime.now().format(START_TIME);
        for (int n = 1; ; n++) {
            Path run = dir.resolve(n == 1 ? stem : stem + "-" + n);
            try {
                Files.createDirectory(run);
            } catch (FileAlreadyExistsException taken) {
                continue; // another run started in the same second: try the next suffix
            } catch (IOException e) {
                throw new IllegalArgumentException(option + " " + dir + ": cannot create a run folder there ("
                        + OutputPaths.reason(e) + ")");
            }
            OutputPaths.created(run);
            Locks.holdFolder(run, "the run folder " + run, note -> System.out.println("handsim: " + note));
            return run;
        }
    }

    /**
     * The folder {@code option} names for one run, held by this process alone ({@link Locks}):
     * created, or an existing empty folder; a folder that already holds files (another run's?)
     * is refused. {@code inside} names what the run writes there (checked by {@link OutputPaths}).
     */
    static Path claimGiven(String option, Path dir, String... inside) {
        new OutputPaths().heldFolder(option, dir, inside).check();
        try (Stream<Path> files = Files.list(dir)) {
            if (files.anyMatch(f -> !Locks.isLockFile(f.getFileName().toString()))) {
                throw new IllegalArgumentException(option + " " + dir + " already holds files (another run's?): give "
                        + "a new or empty folder");
            }
        } catch (IOException e) {
            throw new IllegalArgumentException(option + " " + dir + ": cannot read it (" + OutputPaths.reason(e) + ")");
        }
        return dir;
    }

    /**
     * Holds the existing run folder {@code dir} that {@code option} names ({@code train --resume
     * RUN}) for this process alone: a second process on it is refused at once.
     */
    static void hold(String option, Path dir) {
        if (!Files.isDirectory(dir)) {
            throw new IllegalArgumentException(option + " " + dir + " is not a run folder (no such folder)");
        }
        Locks.holdFolder(dir, option + " " + dir, note -> System.out.println("handsim: " + note));
    }

    /** Gives up a claimed folder that a failed run left empty (a folder with files in it stays). */
    static void release(Path dir) {
        Locks.release(dir);
        try {
            Files.deleteIfExists(dir);
        } catch (DirectoryNotEmptyException | SecurityException kept) {
            // it holds what the run wrote: keep it
        } catch (IOException e) {
            // nothing more to do: the failure that brought us here is what gets reported
        }
    }

    /** A run folder's name without its start time (KIND__NAME__SEED); other folders keep their name. */
    static String withoutStartTime(Path run) {
        return run.getFileName().toString().replaceFirst("__\\d{8}-\\d{6}(-\\d+)?$", "");
    }
}
