package handsim.evaluation;

import handsim.config.Json;
import java.nio.file.Path;

/**
 * What an evaluation is asked for (the options of {@code handsim evaluate}); the task's definition
 * checks the ones that depend on the task.
 *
 * @param task the task's name
 * @param object the object thrown (configs/objects)
 * @param controller nominal or learned
 * @param plan every throw chosen by the twin-world planner ({@link handsim.planning.ThrowPlanner})
 * @param seed the seed of the first episode or trial; episode i has seed + i
 * @param loops height and sensitivity: throws per episode after the first catch; flip: the most loops in a row
 * @param episodes episodes to run (height, flip, sensitivity)
 * @param tests box positions to try (box)
 * @param throwHeight height: every throw's goal apex (m), or null
 * @param goals the goals file read ({@link GoalsFile}: heights for the height task, box centres for the box task), or null
 * @param copies sensitivity: copies of every episode, or null for no sensitivity run
 * @param nudge sensitivity: the launch velocity nudge (m/s)
 * @param csv where the per-loop (per-trial) rows go, or null
 * @param plot where the chart goes, or null
 * @param exported whether the run's one episode is also exported as an animation
 */
public record EvaluationRequest(String task, String object, String controller, boolean plan, long seed, int loops, int episodes,
        int tests, Double throwHeight, Json goals, Integer copies, double nudge, Path csv, Path plot, boolean exported) {

    /** The controller as printed and in the charts' titles: with a planner, "learned + planner". */
    public String controllerLabel() {
        return plan ? controller + " + planner" : controller;
    }
}
