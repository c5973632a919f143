package handsim.taskdef;

import handsim.evaluation.EvaluationRequest;
import handsim.evaluation.EvaluationSetup;
import handsim.evaluation.TaskEvaluation;
import handsim.task.HeightGoals;
import handsim.task.ThrowTask;
import java.util.List;

/**
 * One task of the paper (sec. 4) as handsim runs it, from its file {@code configs/tasks/NAME.json}
 * parsed once: the tasks it makes (each holds one episode's goals, so one per worker), how many
 * loops its evaluation runs by default, which options of {@code evaluate} it takes and the
 * evaluation it runs, and how a scene draws and steers its goal. {@link TaskDefinitions} maps the
 * names to the definitions; nothing else tells the tasks apart by name.
 */
public interface TaskDefinition {

    /** The name runs ask for it by ({@code --task}, a training config's {@code run.task}). */
    String name();

    /** A new task for {@code object}; an object the task cannot take is refused by name. */
    ThrowTask newTask(String object);

    /** The loops (throws) an evaluation episode makes when {@code --loops} is not given. */
    int defaultEvaluationLoops();

    /**
     * Refuses the options of {@code request} this task does not take, and a goals file it cannot
     * read, in one line naming the option; before any work starts.
     */
    void check(EvaluationRequest request);

    /** The evaluation {@code request} asks for ({@link #check checked} first): a sensitivity run with copies, else the task's own. */
    TaskEvaluation evaluation(EvaluationRequest request, EvaluationSetup setup);

    /** Whether its evaluation counts loops in a row until a throw fails (episodes two runs can compare seed by seed). */
    default boolean countsLoopsInARow() {
        return false;
    }

    /**
     * The parts of the controller this task adds by hand for {@code object}, each named with the
     * field of the task's file that sets it (the flip task's catch, release and arm rest); none
     * for a task that runs the controller as configs/controller.json makes it.
     */
    default List<String> handDesignedParts(String object) {
        return List.of();
    }

    /**
     * A new task for {@code object} with the hooks a scene draws and moves its goal by: the
     * height task aims at {@code goals} (shared with whoever steers them) and keeps them inside
     * [{@code lowest}, {@code highest}] m; the others ignore both.
     */
    SteeredTask steered(String object, HeightGoals goals, double lowest, double highest);
}
