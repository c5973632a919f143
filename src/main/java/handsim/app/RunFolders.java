package handsim.app;

import handsim.config.Home;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;

/** Run folders of demo, train and warmstart: {@code KIND__NAME__SEED__yyyyMMdd-HHmmss}, under runs/ unless told otherwise. */
final class RunFolders {

    private static final DateTimeFormatter START_TIME = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss");

    private RunFolders() {
    }

    /** A new run's folder, named by what it is and when it started, in {@code base} (null: the project's runs/). */
    static Path next(Path base, String kind, String name, long seed) {
        Path dir = base != null ? base : Home.resolve("runs");
        return dir.resolve(kind + "__" + name + "__" + seed + "__" + LocalDateTime.now().format(START_TIME));
    }

    /** A run folder's name without its start time (KIND__NAME__SEED); other folders keep their name. */
    static String withoutStartTime(Path run) {
        return run.getFileName().toString().replaceFirst("__\\d{8}-\\d{6}$", "");
    }
}
