package handsim.evaluation;

import handsim.math.Vec3;
import java.nio.file.Path;
import java.util.List;

/**
 * What an evaluation is asked for (the options of {@code handsim evaluate}, checked).
 *
 * @param task height, box or flip
 * @param object the object thrown (configs/objects)
 * @param controller nominal or learned
 * @param plan every throw chosen by a {@link ThrowPlanner}
 * @param seed the seed of the first episode or trial; episode i has seed + i
 * @param loops height and sensitivity: throws per episode after the first catch; flip: the most loops in a row
 * @param episodes episodes to run (height, flip, sensitivity)
 * @param tests box positions to try (box)
 * @param throwHeight height: every throw's goal apex (m), or null
 * @param heightGoals height: the goals in turn (m), or null
 * @param boxGoals box: the box centres to try (m, world), or null for seeded ones
 * @param copies sensitivity: copies of every episode, or null for no sensitivity run
 * @param nudge sensitivity: the launch velocity nudge (m/s)
 * @param csv where the per-loop (per-trial) rows go, or null
 * @param plot where the chart goes, or null
 */
public record EvaluationRequest(String task, String object, String controller, boolean plan, long seed, int loops, int episodes,
        int tests, Double throwHeight, double[] heightGoals, List<Vec3> boxGoals, Integer copies, double nudge, Path csv, Path plot) {

    /** The controller as printed and in the charts' titles: with a planner, "learned + planner". */
    public String controllerLabel() {
        return plan ? controller + " + planner" : controller;
    }
}
