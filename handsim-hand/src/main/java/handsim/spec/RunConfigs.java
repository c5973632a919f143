package handsim.spec;

import handsim.config.ConfigSet;
import handsim.config.Json;
import handsim.control.ControllerConfig;
import handsim.evaluation.EvaluationConfig;
import handsim.kin.Kinematics;
import handsim.model.HandModel;
import handsim.model.ModelLoader;
import handsim.planning.PlannerConfig;
import handsim.sim.ObjectSpec;
import handsim.sim.SimConfig;
import handsim.task.EpisodeLimits;
import handsim.task.LaunchDistribution;
import handsim.task.TaskContext;
import handsim.taskdef.FlipDefinition;
import handsim.taskdef.HeightDefinition;
import handsim.taskdef.TaskDefinition;
import handsim.taskdef.TaskDefinitions;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Function;

/**
 * A run's configuration of the arm and hand, parsed once from its {@link ConfigSet} (the
 * project's files with the run's overrides, or a run's record): the model, the physics, the
 * controller, the episodes and launches, the objects, the tasks' definitions, the planner and
 * how evaluations report. Every part is parsed the first time it is asked for and kept; the
 * parts are immutable, so workers share them.
 */
public final class RunConfigs {

    public static final String MODEL = "models/arm_hand.json";
    /** The limits a model's joints are checked against ({@code handsim.model.Physiology}), read with the model so that it travels with it. */
    public static final String PHYSIOLOGY = "models/physiology.json";
    public static final String SIM = "configs/sim.json";
    public static final String CONTROLLER = "configs/controller.json";
    public static final String EPISODE = "configs/episode.json";
    public static final String LAUNCH = "configs/launch.json";
    public static final String PLANNER = "configs/planner.json";
    public static final String EVALUATION = "configs/evaluation.json";

    private final ConfigSet files;
    private final Map<String, Object> parsed = new HashMap<>();

    public RunConfigs(ConfigSet files) {
        this.files = files;
    }

    /**
     * The project's files for a run of {@code task}: the fields of the task's file in {@code taskSet}
     * changed, and the physics' {@code solver.stepper} set to {@code stepper} (null: the file's).
     * The record ({@link #files}) then holds both documents as the run read them.
     */
    public static RunConfigs ofProject(String task, Map<String, String> taskSet, String stepper) {
        return ofProject(Map.of(task, taskSet), stepper);
    }

    /** The same for the tasks named in {@code taskSets}, each with the fields of its file changed. */
    public static RunConfigs ofProject(Map<String, Map<String, String>> taskSets, String stepper) {
        Map<String, Map<String, String>> overrides = new LinkedHashMap<>();
        taskSets.forEach((task, fields) -> overrides.put(TaskDefinitions.file(task), fields));
        if (stepper != null) {
            overrides.put(SIM, Map.of("solver.stepper", stepper));
        }
        return new RunConfigs(ConfigSet.fromFiles(overrides));
    }

    /** The documents behind these configs (what the run's record holds). */
    public ConfigSet files() {
        return files;
    }

    public HandModel model() {
        return part(MODEL, j -> ModelLoader.parse(j, physiology()));
    }

    /**
     * {@code models/physiology.json} as this run read it (JSON text), what its model is checked
     * against; a record made before the physiology was one of its documents uses the project's.
     */
    public String physiology() {
        return files.replays() && !files.has(PHYSIOLOGY) ? ModelLoader.physiologyText() : files.get(PHYSIOLOGY).node().toString();
    }

    public SimConfig sim() {
        return part(SIM, SimConfig::parse);
    }

    public ControllerConfig controller() {
        return part(CONTROLLER, ControllerConfig::parse);
    }

    public EpisodeLimits limits() {
        return part(EPISODE, EpisodeLimits::parse);
    }

    public LaunchDistribution launches() {
        return part(LAUNCH, LaunchDistribution::parse);
    }

    public EvaluationConfig evaluation() {
        return part(EVALUATION, EvaluationConfig::parse);
    }

    /** The object {@code name} ({@code configs/objects/NAME.json}); an unknown name is refused in one line. */
    public ObjectSpec object(String name) {
        String file = objectFile(name);
        if (!name.matches("[A-Za-z0-9_-]+") || !files.has(file)) {
            throw new IllegalArgumentException("unknown object \"" + name + "\" (no " + file + ")");
        }
        return part(file, ObjectSpec::parse);
    }

    /** Where the object {@code name} is described: {@code configs/objects/NAME.json}. */
    public static String objectFile(String name) {
        return "configs/objects/" + name + ".json";
    }

    /** What the tasks are measured from: the controller's nominal throws, the neutral palm centre, the ground. */
    public synchronized TaskContext taskContext() {
        TaskContext context = (TaskContext) parsed.get("task context");
        if (context == null) {
            HandModel m = model();
            context = new TaskContext(controller().nominalThrows(),
                    new Kinematics(m).siteFrame(m.site("palm_center"), m.poseVector("neutral")).origin(), sim().groundHeight());
            parsed.put("task context", context);
        }
        return context;
    }

    /** The task {@code name}'s definition from its configs/tasks file as this run resolved it; an unknown name is refused. */
    public TaskDefinition task(String name) {
        String file = TaskDefinitions.file(name);
        return part(file, j -> TaskDefinitions.define(name, j, this::taskContext));
    }

    /** The height task's definition, as {@link #task} gives it. */
    public HeightDefinition height() {
        return part(TaskDefinitions.file(HeightDefinition.NAME), j -> TaskDefinitions.height(j, this::taskContext));
    }

    /** The flip task's definition, as {@link #task} gives it. */
    public FlipDefinition flip() {
        return part(TaskDefinitions.file(FlipDefinition.NAME), j -> TaskDefinitions.flip(j, this::taskContext));
    }

    /**
     * The planner's settings ({@code configs/planner.json}) with {@code object}'s own if it has
     * some; an entry under {@code objects} for an object with no file is refused by name.
     */
    public PlannerConfig planner(String object) {
        Json file = files.get(PLANNER);
        if (file.has("objects")) {
            Json objects = file.get("objects");
            for (String name : objects.fieldNames()) {
                if (!files.has(objectFile(name))) {
                    throw objects.fieldError(name, "no such object (no " + objectFile(name) + ")");
                }
            }
        }
        return part(PLANNER + " for " + object, j -> PlannerConfig.parse(file, object));
    }

    @SuppressWarnings("unchecked")
    private synchronized <T> T part(String key, Function<Json, T> parse) {
        Object p = parsed.get(key);
        if (p == null) {
            Json j = files.get(key.split(" ")[0]);
            p = parse.apply(j);
            parsed.put(key, p);
        }
        return (T) p;
    }
}
