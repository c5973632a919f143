package handsim.taskdef;

import handsim.evaluation.EvaluationRequest;
import handsim.evaluation.EvaluationSetup;
import handsim.evaluation.FlipEvaluation;
import handsim.evaluation.SensitivityEvaluation;
import handsim.evaluation.TaskEvaluation;
import handsim.task.FlipTask;
import handsim.task.Goal;
import handsim.task.HeightGoals;
import handsim.task.TaskContext;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;

/**
 * Flip the object and catch it, over and over (paper sec. 4.4, {@link FlipTask}), with the
 * object's own catch, release and arm rest from the config; evaluated by the loops in a row until
 * a throw fails, with or without the twin-world planner ({@code --plan}); nothing to draw or move.
 *
 * @param config configs/tasks/flip.json as the run resolved it, parsed
 * @param context what its tasks are measured from, asked for when the first task is made
 */
public record FlipDefinition(FlipTask.Config config, Supplier<TaskContext> context) implements TaskDefinition {

    public static final String NAME = "flip";

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public FlipTask newTask(String object) {
        return new FlipTask(config, object, context.get().neutralPalm());
    }

    @Override
    public int defaultEvaluationLoops() {
        return config.evaluationLoops();
    }

    @Override
    public void check(EvaluationRequest r) {
        if (r.throwHeight() != null) {
            throw TaskDefinitions.refuse("--throw-height", NAME);
        }
        if (r.goals() != null) {
            throw TaskDefinitions.refuse("--goals", NAME);
        }
        if (r.plan() && r.copies() != null) {
            throw new IllegalArgumentException("--plan goes without --copies");
        }
        TaskDefinitions.checkEpisodes(r);
        newTask(r.object()); // an object the task's file does not list is refused here
    }

    @Override
    public TaskEvaluation evaluation(EvaluationRequest r, EvaluationSetup setup) {
        check(r);
        return r.copies() != null ? new SensitivityEvaluation(r, setup, () -> newTask(r.object()))
                : new FlipEvaluation(r, setup, () -> newTask(r.object()));
    }

    @Override
    public boolean countsLoopsInARow() {
        return true;
    }

    @Override
    public List<String> handDesignedParts(String object) {
        FlipTask.ObjectFlip flip = config.objects().get(object);
        List<String> parts = new ArrayList<>();
        String field = TaskDefinitions.file(NAME) + " objects." + object + ".";
        flip.catchAfterThrow().ifPresent(c -> parts.add("the catch after each throw (" + field + "catch)"));
        flip.release().ifPresent(r -> parts.add("the closed-loop release (" + field + "release)"));
        flip.armRest().ifPresent(r -> parts.add("the arm rest (" + field + "armRest)"));
        return parts;
    }

    @Override
    public SteeredTask steered(String object, HeightGoals goals, double lowest, double highest) {
        return new SteeredTask(newTask(object), Goal.None::new, delta -> "the flip task has no goal to move");
    }
}
