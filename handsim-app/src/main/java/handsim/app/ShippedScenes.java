package handsim.app;

import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.control.ThrowPolicy;
import handsim.evaluation.CatchEvaluation;
import handsim.scene.CatchLoopScene;
import handsim.scene.HeightControl;
import handsim.scene.InteractiveScene;
import handsim.scene.SceneCatalog;
import handsim.scene.SceneSetup;
import handsim.sim.Simulator;
import handsim.spec.RunConfigs;
import handsim.task.HeightGoals;
import handsim.task.StateVector;
import handsim.task.ThrowTask;
import handsim.taskdef.HeightDefinition;
import handsim.taskdef.SteeredTask;
import handsim.taskdef.TaskDefinitions;
import handsim.train.ThrowPolicyFile;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * The scenes this build of handsim can show: the tasks of {@link TaskDefinitions} with the
 * nominal controller or a learned one, for every object in {@code configs/objects/}. The learned
 * controller plays {@code --policy} or the policy shipped for the task and object
 * ({@code models/policies/<task>-<object>.json}); without one, or for a task not built yet, the
 * scene falls back (to nominal, to the height task) with a note.
 *
 * <p>To plug in a task: add it to {@link TaskDefinitions}; the scene is the same {@link CatchLoopScene}.
 */
final class ShippedScenes implements SceneCatalog {

    static final List<String> CONTROLLERS = List.of("nominal", "learned");


    private final HeightGoals goals;
    private final HeightControl heightControl;
    private final ControllerOptions.Choice who;
    /** The project's configs with the fields of the tasks' files {@code who} changed. */
    private final RunConfigs configs;
    private final List<String> objects;

    /**
     * {@code goals} are shared by every scene opened (moving the goal survives a switch of
     * object); {@code who} names the learned controller's policy files given (each null when not:
     * the shipped ones) and whether a {@link handsim.planning.ThrowPlanner} chooses the flip
     * task's throws.
     */
    ShippedScenes(HeightGoals goals, HeightControl heightControl, ControllerOptions.Choice who) {
        this.goals = goals;
        this.heightControl = heightControl;
        this.who = who;
        this.configs = who.configs();
        this.objects = listObjects();
    }

    /** Object names from {@code configs/objects/*.json}, the paper's sphere first. */
    private static List<String> listObjects() {
        try (Stream<Path> files = Files.list(Home.resolve("configs/objects"))) {
            List<String> names = new ArrayList<>(files.map(p -> p.getFileName().toString())
                    .filter(n -> n.endsWith(".json")).map(n -> n.substring(0, n.length() - 5)).sorted().toList());
            if (names.remove("sphere")) {
                names.add(0, "sphere");
            }
            return List.copyOf(names);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot list configs/objects", e);
        }
    }

    /**
     * Rejects names this catalog does not list and a --policy file that does not exist (typos on
     * the command line; a missing --opening-policy or --rest-policy file is refused with the
     * options, {@link ControllerOptions#validateSceneOptions}).
     */
    void validate(SceneSetup s) {
        check("--task", s.task(), TaskDefinitions.NAMES);
        check("--object", s.object(), objects);
        check("--controller", s.controller(), CONTROLLERS);
        if (who.policy() != null && !Files.isRegularFile(who.policy())) { // a typo, not a policy that does not fit: refused
            throw new IllegalArgumentException("--policy: no file " + who.policy());
        }
    }

    private static void check(String option, String value, List<String> allowed) {
        if (!allowed.contains(value)) {
            throw new IllegalArgumentException(option + " must be one of " + String.join(", ", allowed) + ", got \"" + value + "\"");
        }
    }

    @Override
    public List<String> tasks() {
        return TaskDefinitions.NAMES;
    }

    @Override
    public List<String> objects() {
        return objects;
    }

    @Override
    public List<String> controllers() {
        return CONTROLLERS;
    }

    @Override
    public Opened open(SceneSetup wanted) {
        List<String> notes = new ArrayList<>();
        SceneSetup shown = wanted;
        if (!TaskDefinitions.NAMES.contains(wanted.task())) {
            notes.add("the " + wanted.task() + " task is not built yet: showing the height task");
            shown = shown.withTask(HeightDefinition.NAME);
        }
        SteeredTask steered;
        try {
            steered = configs.task(shown.task()).steered(shown.object(), goals, heightControl.min(), heightControl.max());
        } catch (IllegalArgumentException | ConfigException e) {
            notes.add(e.getMessage() + ": showing the height task");
            shown = shown.withTask(HeightDefinition.NAME);
            steered = configs.height().steered(shown.object(), goals, heightControl.min(), heightControl.max());
        }
        ThrowTask task = steered.task();
        ThrowTask chosen = task;
        ThrowPolicy throwPolicy = obs -> chosen.nominalThrow();
        if (shown.controller().equals("learned")) {
            try {
                throwPolicy = learned(shown, task);
            } catch (IllegalArgumentException e) {
                notes.add(e.getMessage() + ": using the nominal controller");
                shown = shown.withController("nominal");
            }
        }
        CatchEvaluation evaluation = new CatchEvaluation(configs.controller(), configs.limits(), configs.launches(),
                configs.object(shown.object()), task, throwPolicy);
        Simulator sim = Wiring.simulator(configs.model(), configs.sim());
        Simulator twin = null;
        if (who.plan() && task.goalSize() != 0) {
            notes.add("the throw planner chooses the flip task's throws only: the " + task.name() + " task's are not planned");
        } else if (who.plan()) {
            twin = Wiring.twinSimulator(sim);
            evaluation = evaluation.planned(configs.planner(shown.object()), twin);
        }
        InteractiveScene scene = new CatchLoopScene(sim, evaluation, steered, shown.seed(), heightControl, twin);
        return new Opened(scene, shown, notes);
    }

    /**
     * The learned throw policy for a setup: {@code --policy} if given (and meant for this task
     * and object), else the shipped one; each episode's first throw by {@code --opening-policy}
     * if given (and meant for them), else, with the shipped policy, by the shipped opening; the
     * throws from one rest by {@code --rest-policy} likewise, else with the shipped policy by the
     * shipped rest policy, when one ships; the exception's message says why there is none.
     */
    private ThrowPolicy learned(SceneSetup setup, ThrowTask task) {
        Path file = who.policy();
        Path opening = who.opening() != null && matches(who.opening(), setup) ? who.opening() : null;
        Path rest = who.rest() != null && matches(who.rest(), setup) ? who.rest() : null;
        if (file == null || !matches(file, setup)) {
            file = ThrowPolicyFile.shipped(setup.task(), setup.object());
            opening = opening != null ? opening : ThrowPolicyFile.shippedOpening(setup.task(), setup.object());
            rest = rest != null ? rest : ThrowPolicyFile.shippedRest(setup.task(), setup.object());
            if (!Files.isRegularFile(file)) {
                throw new IllegalArgumentException("no learned policy for the " + setup.task() + " task with a " + setup.object()
                        + " (none shipped; give --policy FILE)");
            }
        }
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException("learned policy " + file + " does not exist");
        }
        try {
            return ThrowPolicyFile.throwPolicy(file, opening, rest, task, configs.object(setup.object()), StateVector.Hand.of(configs.model()));
        } catch (ConfigException e) {
            throw new IllegalArgumentException("learned policy " + file + " cannot be read (" + e.getMessage() + ")", e);
        }
    }

    /** Whether the given --policy file exists and was trained for this task and object (else the shipped one is used). */
    private static boolean matches(Path file, SceneSetup setup) {
        if (!Files.isRegularFile(file)) {
            return true; // reported as missing by the caller
        }
        try {
            ThrowPolicyFile f = ThrowPolicyFile.load(file);
            return f.task().equals(setup.task()) && f.object().equals(setup.object());
        } catch (ConfigException e) {
            return true; // reported as unreadable by the caller
        }
    }
}
