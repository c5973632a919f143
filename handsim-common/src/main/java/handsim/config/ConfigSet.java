package handsim.config;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Files;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The configuration documents of one run, by their path under the project root ({@code
 * configs/sim.json}, {@code models/arm_hand.json}, ...): each read once, with the run's overrides
 * applied ({@code --set}, {@code --task-set}; {@link Json#withOverrides}), and recorded as read, so
 * that the run's record repeats it from the record alone ({@link #replaying}). Safe to share
 * between workers.
 */
public final class ConfigSet {

    private final Map<String, Map<String, String>> overrides;
    private final Json record;
    private final Map<String, Json> read = new LinkedHashMap<>();

    private ConfigSet(Map<String, Map<String, String>> overrides, Json record) {
        this.overrides = Map.copyOf(overrides);
        this.record = record;
    }

    /** The project's files, each with the fields of {@code overrides} (per path) changed. */
    public static ConfigSet fromFiles(Map<String, Map<String, String>> overrides) {
        return new ConfigSet(overrides, null);
    }

    /** The project's files as they are. */
    public static ConfigSet fromFiles() {
        return fromFiles(Map.of());
    }

    /** The documents of a run's record ({@link #toJson}): nothing is read from the project's files. */
    public static ConfigSet replaying(Json record) {
        return new ConfigSet(Map.of(), record);
    }

    /** Document {@code path}, read (and overridden) the first time it is asked for. */
    public synchronized Json get(String path) {
        Json j = read.get(path);
        if (j == null) {
            j = record != null ? fromRecord(path) : Json.load(Home.resolve(path), overrides.getOrDefault(path, Map.of()));
            read.put(path, j);
        }
        return j;
    }

    /** Whether document {@code path} exists: a file of the project, or an entry of the record. */
    public boolean has(String path) {
        return record != null ? record.has(path) : Files.isRegularFile(Home.resolve(path));
    }

    /** Whether this set repeats a recorded run. */
    public boolean replays() {
        return record != null;
    }

    /** The overrides given for {@code path} (empty when replaying: the record holds them applied). */
    public Map<String, String> overrides(String path) {
        return overrides.getOrDefault(path, Map.of());
    }

    private Json fromRecord(String path) {
        if (!record.has(path)) {
            throw record.error("the record holds no " + path + ", which this run reads");
        }
        Json entry = record.get(path);
        return Json.of(record.source() + ": " + path, entry.node());
    }

    /** The documents read so far, in the order they were first asked for: the run's record of its configuration. */
    public synchronized ObjectNode toJson() {
        ObjectNode o = JsonNodeFactory.instance.objectNode();
        read.forEach((path, j) -> o.set(path, j.node().deepCopy()));
        return o;
    }
}
