package handsim.taskdef;

import handsim.math.Vec3;
import handsim.task.Goal;
import handsim.task.ThrowTask;
import java.util.function.Function;
import java.util.function.Supplier;

/**
 * A task as a scene shows it: the task, its current goal for drawing, and how a watcher's request
 * moves the goal by a displacement (m, world), answered in one line.
 */
public record SteeredTask(ThrowTask task, Supplier<Goal> goal, Function<Vec3, String> moveGoal) {
}
