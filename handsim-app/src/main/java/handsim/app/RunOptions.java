package handsim.app;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import picocli.CommandLine.Option;

/**
 * A learning run's folder, declared once for the commands that make one ({@code train}, {@code
 * dagger}): a new run's config with its overrides, or the folder of a run to continue, and where
 * new run folders go.
 */
final class RunOptions {

    @Option(names = "--config", paramLabel = "FILE", description = "the run's config, e.g. configs/train/height.json")
    Path config;

    @Option(names = "--set", paramLabel = "KEY=VALUE", description = "override a config field, e.g. --set run.workers=1 "
            + "(repeatable; dotted paths into the file)")
    List<String> overrides = List.of();

    @Option(names = "--resume", paramLabel = "RUN_DIR", description = "continue the run in this folder (train: from its last checkpoint)")
    Path resume;

    @Option(names = "--runs", paramLabel = "DIR", description = "where new run folders go (default: runs/)")
    Path runs;

    /** Refuses neither or both of --config and --resume, and --set on a resumed run. */
    void validate() {
        if ((config == null) == (resume == null)) {
            throw new IllegalArgumentException("give either --config FILE (a new run) or --resume RUN_DIR");
        }
        if (resume != null && !overrides.isEmpty()) {
            throw new IllegalArgumentException("a resumed run keeps the config saved in its folder: --set goes with --config only");
        }
    }

    /** The --config file with the --set overrides (KEY=VALUE, dotted paths into the file) applied. */
    Json configFile() {
        return configFile(config, overrides);
    }

    /** {@code config} with {@code overrides} ({@code --set} options) applied. */
    static Json configFile(Path config, List<String> overrides) {
        return Json.load(config, keyValues(overrides));
    }

    /** {@code --set} options as dotted keys to JSON values, in order; a malformed one is named. */
    static Map<String, String> keyValues(List<String> overrides) {
        return keyValues("--set", overrides);
    }

    /** Options {@code option} KEY=VALUE as dotted keys to JSON values, in order; a malformed one is named. */
    static Map<String, String> keyValues(String option, List<String> overrides) {
        Map<String, String> kv = new LinkedHashMap<>();
        for (String o : overrides) {
            int eq = o.indexOf('=');
            if (eq <= 0) {
                throw new IllegalArgumentException(option + " takes KEY=VALUE, got \"" + o + "\"");
            }
            kv.put(o.substring(0, eq), o.substring(eq + 1));
        }
        return kv;
    }

    /** What a run folder of {@code command} records about how the run was made: the command line, seed, commit, time, Java and cores. */
    ObjectNode provenance(String command, Path initActor, long seed) {
        return provenance(commandLine(command, config, overrides) + (initActor == null ? "" : " --init-actor " + shellWord(initActor.toString())),
                seed);
    }

    /** {@code scripts/handsim COMMAND --config CONFIG --set ...}, each word quoted for a shell where it needs it. */
    static String commandLine(String command, Path config, List<String> overrides) {
        StringBuilder line = new StringBuilder("scripts/handsim " + command + " --config " + shellWord(config.toString()));
        overrides.forEach(o -> line.append(" --set ").append(shellWord(o)));
        return line.toString();
    }

    /** A word as a POSIX shell reads it back: as is when plain, else in single quotes. */
    static String shellWord(String word) {
        return word.matches("[A-Za-z0-9_./=:,+@%-]+") ? word : "'" + word.replace("'", "'\\''") + "'";
    }

    /** The run folder's record of a run made by {@code commandLine}: it, the seed, commit, time, Java and cores. */
    static ObjectNode provenance(String commandLine, long seed) {
        ObjectNode p = Json.mapper().createObjectNode();
        p.put("command", commandLine);
        p.put("seed", seed);
        p.put("commit", Provenance.gitCommit());
        p.put("started", LocalDateTime.now().toString());
        p.put("java", System.getProperty("java.version"));
        p.put("cores", Runtime.getRuntime().availableProcessors());
        return p;
    }
}
