package handsim.task;

import handsim.config.Home;
import handsim.config.Json;
import handsim.control.NominalThrows;
import handsim.math.Vec3;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The shipped tasks, built from {@code configs/tasks/NAME.json}: a fresh, independent instance
 * per call (tasks hold an episode's goals: one per thread).
 *
 * @param nominal the hand-tuned throws per apex height (configs/controller.json)
 * @param neutralPalm the palm centre in the neutral pose (m, world)
 * @param groundHeight height of the ground plane (m)
 * @param overrides per task name, fields of its file to replace ({@code KEY=VALUE}, dotted paths,
 *     as {@link Json#withOverrides} reads them): a variant of a task without a file of its own
 */
public record Tasks(NominalThrows nominal, Vec3 neutralPalm, double groundHeight, Map<String, Map<String, String>> overrides) {

    /** Task names, in the viewer's order. */
    public static final List<String> NAMES = List.of("height", "box", "flip");

    public Tasks {
        Map<String, Map<String, String>> copy = new LinkedHashMap<>();
        overrides.forEach((task, kv) -> {
            if (!NAMES.contains(task)) {
                throw unknown(task);
            }
            copy.put(task, Collections.unmodifiableMap(new LinkedHashMap<>(kv)));
        });
        overrides = Collections.unmodifiableMap(copy);
    }

    private static IllegalArgumentException unknown(String name) {
        return new IllegalArgumentException("unknown task \"" + name + "\"; tasks: " + String.join(", ", NAMES));
    }

    /** The shipped tasks as their files say. */
    public Tasks(NominalThrows nominal, Vec3 neutralPalm, double groundHeight) {
        this(nominal, neutralPalm, groundHeight, Map.of());
    }

    /** These tasks with {@code fields} of {@code task}'s file replaced (on top of any replaced before). */
    public Tasks withOverrides(String task, Map<String, String> fields) {
        Map<String, Map<String, String>> all = new LinkedHashMap<>(overrides);
        Map<String, String> merged = new LinkedHashMap<>(all.getOrDefault(task, Map.of()));
        merged.putAll(fields);
        all.put(task, merged);
        return new Tasks(nominal, neutralPalm, groundHeight, all);
    }

    /**
     * A new task {@code name} for {@code object} with its config; the height task over its
     * config's goal range. The flip task fails for an object its config does not list.
     */
    public ThrowTask create(String name, String object) {
        return switch (name) {
            case "height" -> height(null);
            case "box" -> new BoxTask(BoxTask.Config.parse(config("box")), nominal, neutralPalm);
            case "flip" -> new FlipTask(FlipTask.Config.parse(config("flip")), object, neutralPalm);
            default -> throw unknown(name);
        };
    }

    /** Reads task {@code name}'s file with {@code fields} changed, as tasks do: a bad field fails here, naming it and its value. */
    public static void check(String name, Map<String, String> fields) {
        switch (name) {
            case "height" -> HeightTask.Config.parse(config(name, fields));
            case "box" -> BoxTask.Config.parse(config(name, fields));
            case "flip" -> FlipTask.Config.parse(config(name, fields));
            default -> throw unknown(name);
        }
    }

    /** The height task aiming at {@code goals}, or at its config's goal range when null. */
    public HeightTask height(HeightGoals goals) {
        HeightTask.Config c = HeightTask.Config.parse(config("height"));
        return new HeightTask(c, goals != null ? goals : new HeightGoals(c.low(), c.high()), nominal, neutralPalm,
                groundHeight);
    }

    /** {@code configs/tasks/NAME.json} as these tasks read it: with their overrides of it applied. */
    public Json config(String name) {
        return config(name, overrides.getOrDefault(name, Map.of()));
    }

    /** {@code configs/tasks/NAME.json} with {@code fields} changed ({@link Json#withOverrides}). */
    public static Json config(String name, Map<String, String> fields) {
        return Json.load(Home.resolve("configs/tasks/" + name + ".json"), fields);
    }

    /** {@code configs/tasks/height.json}. */
    public static HeightTask.Config heightConfig() {
        return HeightTask.Config.parse(config("height", Map.of()));
    }
}
