package handsim.taskdef;

import handsim.evaluation.EvaluationRequest;
import handsim.evaluation.EvaluationSetup;
import handsim.evaluation.GoalsFile;
import handsim.evaluation.HeightEvaluation;
import handsim.evaluation.SensitivityEvaluation;
import handsim.evaluation.TaskEvaluation;
import handsim.task.Goal;
import handsim.task.HeightGoals;
import handsim.task.HeightTask;
import handsim.task.TaskContext;
import java.util.Locale;
import java.util.function.Supplier;

/**
 * Throw to a desired height (paper sec. 4.2, {@link HeightTask}): goals drawn from the config's
 * range, or one height ({@code --throw-height}), or a list ({@code --goals} heights); evaluated by
 * the height errors (Fig. 5); the goal drawn as a plane, raised and lowered by a watcher.
 *
 * @param config configs/tasks/height.json as the run resolved it, parsed
 * @param context what its tasks are measured from, asked for when the first task is made
 */
public record HeightDefinition(HeightTask.Config config, Supplier<TaskContext> context) implements TaskDefinition {

    public static final String NAME = "height";

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public HeightTask newTask(String object) {
        return newTask((HeightGoals) null);
    }

    /** The task aiming at {@code goals}, or at the config's goal range when null. */
    public HeightTask newTask(HeightGoals goals) {
        return new HeightTask(config, goals != null ? goals : new HeightGoals(config.low(), config.high()), context.get().nominal(),
                context.get().neutralPalm(), context.get().groundHeight());
    }

    @Override
    public int defaultEvaluationLoops() {
        return config.evaluationThrows();
    }

    @Override
    public void check(EvaluationRequest r) {
        if (r.plan()) {
            throw TaskDefinitions.refuse("--plan", NAME);
        }
        if (r.throwHeight() != null && !config.allowsGoal(r.throwHeight())) {
            throw new IllegalArgumentException("--throw-height must be in " + config.goalLimits() + ", got " + r.throwHeight());
        }
        if (r.throwHeight() != null && r.goals() != null) {
            throw new IllegalArgumentException("--throw-height goes without --goals");
        }
        if (r.goals() != null) {
            GoalsFile.heights(r.goals(), config);
        }
        TaskDefinitions.checkEpisodes(r);
    }

    @Override
    public TaskEvaluation evaluation(EvaluationRequest r, EvaluationSetup setup) {
        check(r);
        double[] list = r.goals() != null ? GoalsFile.heights(r.goals(), config) : null;
        // a worker's goals: the listed ones in turn, one fixed height, or seeded random ones
        Supplier<HeightTask> tasks = () -> newTask(list != null ? HeightGoals.sequence(list)
                : r.throwHeight() != null ? HeightGoals.fixed(r.throwHeight()) : null);
        return r.copies() != null ? new SensitivityEvaluation(r, setup, tasks::get) : new HeightEvaluation(r, setup, tasks);
    }

    @Override
    public SteeredTask steered(String object, HeightGoals goals, double lowest, double highest) {
        HeightTask task = newTask(goals);
        return new SteeredTask(task, () -> new Goal.Height(goals.current(), context.get().neutralPalm()),
                delta -> move(goals, delta.y(), lowest, highest));
    }

    /** Raises or lowers {@code goals} by {@code dy} (m), kept inside [lowest, highest] m. */
    private static String move(HeightGoals goals, double dy, double lowest, double highest) {
        if (Math.abs(dy) < 1e-12) {
            return "the height task has no box to move (raise or lower the height goal instead)";
        }
        boolean up = dy > 0;
        double d = up ? Math.min(dy, highest - goals.high()) : Math.max(dy, lowest - goals.low());
        if (up ? d < 1e-9 : d > -1e-9) {
            return String.format(Locale.ROOT, "height goals already at their %s bound (%.2f-%.2f m allowed)",
                    up ? "upper" : "lower", lowest, highest);
        }
        goals.shift(d);
        return String.format(Locale.ROOT, "next throws aim at %s", goals.high() > goals.low()
                ? String.format(Locale.ROOT, "%.2f-%.2f m (now %.2f m)", goals.low(), goals.high(), goals.current())
                : String.format(Locale.ROOT, "%.2f m", goals.current()));
    }
}
