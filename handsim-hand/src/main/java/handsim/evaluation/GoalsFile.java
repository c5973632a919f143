package handsim.evaluation;

import handsim.config.Json;
import handsim.math.Vec3;
import handsim.task.HeightTask;
import java.util.ArrayList;
import java.util.List;

/**
 * A goals file of {@code evaluate --goals}: {@code {"heights": [h, ...]}} (one apex per throw, in
 * turn, m) or {@code {"boxes": [[x, y, z], ...]}} (one box centre per trial, m, world).
 */
public final class GoalsFile {

    private GoalsFile() {
    }

    /** The heights of a goals file, each a goal {@code height} allows. */
    public static double[] heights(Json file, HeightTask.Config height) {
        return read(file, "heights", 1, height).stream().mapToDouble(g -> g[0]).toArray();
    }

    /** The box centres of a goals file. */
    public static List<Vec3> boxes(Json file) {
        return read(file, "boxes", 3, null).stream().map(b -> new Vec3(b[0], b[1], b[2])).toList();
    }

    /** The goals listed under {@code key}, each with {@code size} numbers. */
    private static List<double[]> read(Json j, String key, int size, HeightTask.Config height) {
        List<double[]> out = new ArrayList<>();
        for (Json g : j.array(key)) {
            double[] goal = size == 1 ? new double[] {g.asNumber()} : g.asNumbers(size);
            if (height != null && !height.allowsGoal(goal[0])) {
                throw g.error("a height goal must lie in " + height.goalLimits() + ", got " + goal[0]);
            }
            out.add(goal);
        }
        if (out.isEmpty()) {
            throw j.fieldError(key, "at least one goal is needed");
        }
        j.requireNoUnknownFields();
        return out;
    }
}
