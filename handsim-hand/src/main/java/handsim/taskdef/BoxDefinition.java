package handsim.taskdef;

import handsim.evaluation.BoxEvaluation;
import handsim.evaluation.EvaluationRequest;
import handsim.evaluation.EvaluationSetup;
import handsim.evaluation.GoalsFile;
import handsim.evaluation.TaskEvaluation;
import handsim.math.Vec3;
import handsim.task.BoxTask;
import handsim.task.Goal;
import handsim.task.HeightGoals;
import handsim.task.TaskContext;
import java.util.Locale;
import java.util.function.Supplier;

/**
 * Hit a box and catch the rebound (paper sec. 4.3, {@link BoxTask}): one trial per box position,
 * seeded or listed ({@code --goals} boxes), a success after the config's loops in a row;
 * evaluated by the success rate and map (Fig. 8); the box drawn, and moved by a watcher for the
 * next throw-in.
 *
 * @param config configs/tasks/box.json as the run resolved it, parsed
 * @param context what its tasks are measured from, asked for when the first task is made
 */
public record BoxDefinition(BoxTask.Config config, Supplier<TaskContext> context) implements TaskDefinition {

    public static final String NAME = "box";

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public BoxTask newTask(String object) {
        return new BoxTask(config, context.get().nominal(), context.get().neutralPalm());
    }

    /** The hit-and-catch loops in a row a box trial needs. */
    @Override
    public int defaultEvaluationLoops() {
        return config.loopsRequired();
    }

    @Override
    public void check(EvaluationRequest r) {
        if (r.plan()) {
            throw TaskDefinitions.refuse("--plan", NAME);
        }
        if (r.copies() != null) {
            throw TaskDefinitions.refuse("--copies", NAME);
        }
        if (r.throwHeight() != null) {
            throw TaskDefinitions.refuse("--throw-height", NAME);
        }
        if (r.exported() && (r.episodes() != 1 || r.tests() != 1)) {
            throw new IllegalArgumentException("--export goes with one trial: --tests 1");
        }
        if (r.goals() != null) {
            GoalsFile.boxes(r.goals());
        }
    }

    @Override
    public TaskEvaluation evaluation(EvaluationRequest r, EvaluationSetup setup) {
        check(r);
        return new BoxEvaluation(r, setup, () -> newTask(r.object()), r.goals() != null ? GoalsFile.boxes(r.goals()) : null);
    }

    @Override
    public SteeredTask steered(String object, HeightGoals goals, double lowest, double highest) {
        BoxTask task = newTask(object);
        return new SteeredTask(task, () -> new Goal.Box(task.shownBox(), cube()), delta -> {
            Vec3 at = task.nextBox().plus(delta);
            task.placeAt(at);
            return String.format(Locale.ROOT, "the box moves to (%.2f, %.2f, %.2f) m from the next throw-in", at.x(), at.y(), at.z());
        });
    }

    private Vec3 cube() {
        return new Vec3(config.size(), config.size(), config.size());
    }
}
