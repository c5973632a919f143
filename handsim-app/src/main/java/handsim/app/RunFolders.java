package handsim.app;

import handsim.config.Home;
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
 * second gets the name with {@code -2} (then {@code -3}, ...) appended.
 */
final class RunFolders {

    private static final DateTimeFormatter START_TIME = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss");
    /** What a run's name may hold: it becomes part of a folder name. */
    private static final String NAME = "[A-Za-z0-9][A-Za-z0-9._-]*";

    private RunFolders() {
    }

    /**
     * A new run's folder, named by what it is and when it started, created in {@code base}
     * ({@code option}'s value; null: the project's runs/), and claimed for this run alone.
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
                return Files.createDirectory(run);
            } catch (FileAlreadyExistsException taken) {
                // another run started in the same second: try the next suffix
            } catch (IOException e) {
                throw new IllegalArgumentException(option + " " + dir + ": cannot create a run folder there ("
                        + OutputPaths.reason(e) + ")");
            }
        }
    }

    /**
     * The folder {@code option} names for one run: created, or an existing empty folder; a
     * folder that already holds files (another run's?) is refused.
     */
    static Path claimGiven(String option, Path dir) {
        new OutputPaths().folder(option, dir.toAbsolutePath().getParent()).check();
        try {
            return Files.createDirectory(dir);
        } catch (FileAlreadyExistsException exists) {
            if (!Files.isDirectory(dir)) {
                throw new IllegalArgumentException(option + " " + dir + " is a file, not a folder");
            }
            try (Stream<Path> inside = Files.list(dir)) {
                if (inside.findAny().isPresent()) {
                    throw new IllegalArgumentException(option + " " + dir + " already holds files (another run's?): give "
                            + "a new or empty folder");
                }
            } catch (IOException e) {
                throw new IllegalArgumentException(option + " " + dir + ": cannot read it (" + OutputPaths.reason(e) + ")");
            }
            return dir;
        } catch (IOException e) {
            throw new IllegalArgumentException(option + " " + dir + ": cannot create it (" + OutputPaths.reason(e) + ")");
        }
    }

    /** Gives up a claimed folder that a failed run left empty (a folder with files in it stays). */
    static void release(Path dir) {
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
