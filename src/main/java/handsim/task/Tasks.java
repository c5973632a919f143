package handsim.task;

import handsim.config.Home;
import handsim.config.Json;
import handsim.control.NominalThrows;
import handsim.math.Vec3;
import java.util.List;

/**
 * The shipped tasks, built from {@code configs/tasks/NAME.json}: a fresh, independent instance
 * per call (tasks hold an episode's goals: one per thread).
 *
 * @param nominal the hand-tuned throws per apex height (configs/controller.json)
 * @param neutralPalm the palm centre in the neutral pose (m, world)
 * @param groundHeight height of the ground plane (m)
 */
public record Tasks(NominalThrows nominal, Vec3 neutralPalm, double groundHeight) {

    /** Task names, in the viewer's order. */
    public static final List<String> NAMES = List.of("height", "box", "flip");

    /**
     * A new task {@code name} for {@code object} with its shipped config; the height task over
     * its config's goal range. The flip task fails for an object its config does not list.
     */
    public ThrowTask create(String name, String object) {
        return switch (name) {
            case "height" -> height(null);
            case "box" -> new BoxTask(boxConfig(), nominal, neutralPalm);
            case "flip" -> new FlipTask(flipConfig(), object, neutralPalm);
            default -> throw new IllegalArgumentException("unknown task \"" + name + "\"; tasks: " + String.join(", ", NAMES));
        };
    }

    /** The height task aiming at {@code goals}, or at its config's goal range when null. */
    public HeightTask height(HeightGoals goals) {
        HeightTask.Config c = heightConfig();
        return new HeightTask(c, goals != null ? goals : new HeightGoals(c.low(), c.high()), nominal, neutralPalm,
                groundHeight);
    }

    /** {@code configs/tasks/height.json}. */
    public static HeightTask.Config heightConfig() {
        return HeightTask.Config.parse(Json.load(Home.resolve("configs/tasks/height.json")));
    }

    /** {@code configs/tasks/box.json}. */
    public static BoxTask.Config boxConfig() {
        return BoxTask.Config.parse(Json.load(Home.resolve("configs/tasks/box.json")));
    }

    /** {@code configs/tasks/flip.json}. */
    public static FlipTask.Config flipConfig() {
        return FlipTask.Config.parse(Json.load(Home.resolve("configs/tasks/flip.json")));
    }
}
