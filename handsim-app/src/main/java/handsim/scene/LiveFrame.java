package handsim.scene;

import handsim.sim.WorldSnapshot;
import handsim.task.Goal;
import java.util.Map;

/**
 * What a watcher sees of a {@link LiveRun} at one instant; immutable.
 *
 * @param snapshot the world
 * @param status the scene's labelled figures, in display order
 * @param goal the task's goal, for drawing
 * @param speed simulated seconds per wall second asked for (1 = real time)
 * @param paused the clock is paused
 * @param realTimeFactor simulated seconds advanced per wall second, measured over the last
 *     half second or so (NaN until measured)
 * @param sequence counts published frames (a new number means a new snapshot)
 */
public record LiveFrame(WorldSnapshot snapshot, Map<String, String> status, Goal goal, double speed, boolean paused,
        double realTimeFactor, long sequence) {
}
