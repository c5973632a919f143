package handsim.taskdef;

import handsim.config.Home;
import handsim.config.Json;
import handsim.evaluation.EvaluationRequest;
import handsim.task.BoxTask;
import handsim.task.FlipTask;
import handsim.task.HeightTask;
import handsim.task.TaskContext;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

/** The registry of the tasks: each name with the definition it stands for, the one place that tells them apart by name. */
public final class TaskDefinitions {

    /** The tasks, in the viewer's order. */
    public static final List<String> NAMES = List.of(HeightDefinition.NAME, BoxDefinition.NAME, FlipDefinition.NAME);

    private TaskDefinitions() {
    }

    /**
     * Task {@code name} defined by {@code file} (its configs/tasks file as the run resolved it),
     * its tasks measured from {@code context} (asked for when the first task is made).
     */
    public static TaskDefinition define(String name, Json file, Supplier<TaskContext> context) {
        return switch (name) {
            case HeightDefinition.NAME -> height(file, context);
            case BoxDefinition.NAME -> new BoxDefinition(BoxTask.Config.parse(file), context);
            case FlipDefinition.NAME -> flip(file, context);
            default -> throw unknown(name);
        };
    }

    /** The height task defined by {@code file}. */
    public static HeightDefinition height(Json file, Supplier<TaskContext> context) {
        return new HeightDefinition(HeightTask.Config.parse(file), context);
    }

    /** The flip task defined by {@code file}. */
    public static FlipDefinition flip(Json file, Supplier<TaskContext> context) {
        return new FlipDefinition(FlipTask.Config.parse(file), context);
    }

    /** Reads {@code file} as task {@code name} reads it: a bad field is refused, naming it and its value; nothing else is built. */
    public static void check(String name, Json file) {
        define(name, file, null);
    }

    /** Whether task {@code name}'s evaluation runs tests (the box's positions, {@code --tests}) rather than episodes. */
    public static boolean evaluatesTests(String name) {
        return BoxDefinition.NAME.equals(checkName(name));
    }

    /** Refuses a name that is no task, in one line listing the tasks. */
    public static String checkName(String name) {
        if (!NAMES.contains(name)) {
            throw unknown(name);
        }
        return name;
    }

    /** The path of task {@code name}'s file under the project root: {@code configs/tasks/NAME.json}. */
    public static String file(String name) {
        return "configs/tasks/" + checkName(name) + ".json";
    }

    /** Reads {@code configs/tasks/NAME.json} with {@code fields} changed ({@link Json#withOverrides}). */
    public static Json read(String name, Map<String, String> fields) {
        return Json.load(Home.resolve(file(name)), fields);
    }

    /**
     * The fields of task {@code task}'s file that a training run's {@code armRest} and {@code catch}
     * stand for, in run sections that name them instead of a {@code taskSet}: the flip task's
     * object's catch replaced by {@code catchJson} (when not null), and its arm rest left out
     * unless {@code armRest}; the other tasks have neither.
     */
    public static Map<String, String> runFields(String task, String object, boolean armRest, String catchJson) {
        Map<String, String> fields = new LinkedHashMap<>();
        if (checkName(task).equals(FlipDefinition.NAME)) {
            if (catchJson != null) {
                fields.put("objects." + object + ".catch", catchJson);
            }
            if (!armRest) {
                fields.put("objects." + object + ".armRest", "null");
            }
        } else if (armRest || catchJson != null) {
            throw new IllegalArgumentException("only the flip task has an arm rest and a catch to set, and the task is \"" + task + "\"");
        }
        return fields;
    }

    private static IllegalArgumentException unknown(String name) {
        return new IllegalArgumentException("unknown task \"" + name + "\"; tasks: " + String.join(", ", NAMES));
    }

    /** The refusal of an option a task does not take. */
    static IllegalArgumentException refuse(String option, String task) {
        return new IllegalArgumentException(option + " does not go with the " + task + " task");
    }

    /** Checks shared by the tasks that run episodes (height, flip): --export with one episode. */
    static void checkEpisodes(EvaluationRequest r) {
        if (r.exported() && (r.episodes() != 1 || r.copies() != null)) {
            throw new IllegalArgumentException("--export goes with one episode: --episodes 1, without --copies");
        }
    }
}
