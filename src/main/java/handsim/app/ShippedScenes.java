package handsim.app;

import handsim.config.Home;
import handsim.model.HandModel;
import handsim.sim.SimConfig;
import handsim.task.CatchLoopScene;
import handsim.task.HeightControl;
import handsim.task.HeightGoals;
import handsim.task.InteractiveScene;
import handsim.task.SceneCatalog;
import handsim.task.SceneSetup;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * The scenes this build of handsim can show. Today: the height task with the nominal controller,
 * for every object in {@code configs/objects/}. The box and flip tasks and learned controllers
 * are listed (the viewer cycles through them) and fall back to height / nominal with a note
 * until they exist.
 *
 * <p>To plug in a task: implement {@link InteractiveScene} (its goal, status and commands) and
 * build it in {@link #open} for its name. To plug in a learned controller: build the task's
 * evaluation with a {@code ThrowPolicy} read from {@code policy} instead of the nominal one.
 */
final class ShippedScenes implements SceneCatalog {

    static final List<String> TASKS = List.of("height", "box", "flip");
    static final List<String> CONTROLLERS = List.of("nominal", "learned");

    private final HandModel model = Runtime.model(null);
    private final SimConfig simConfig = Runtime.simConfig();
    private final HeightGoals goals;
    private final HeightControl heightControl;
    private final Path policy;
    private final List<String> objects;

    /**
     * {@code goals} are shared by every scene opened (moving the goal survives a switch of
     * object); {@code policy} is the learned controller's file, or null.
     */
    ShippedScenes(HeightGoals goals, HeightControl heightControl, Path policy) {
        this.goals = goals;
        this.heightControl = heightControl;
        this.policy = policy;
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

    /** Rejects names this catalog does not list (a typo on the command line). */
    void validate(SceneSetup s) {
        check("--task", s.task(), TASKS);
        check("--object", s.object(), objects);
        check("--controller", s.controller(), CONTROLLERS);
    }

    private static void check(String option, String value, List<String> allowed) {
        if (!allowed.contains(value)) {
            throw new IllegalArgumentException(option + " must be one of " + String.join(", ", allowed) + ", got \"" + value + "\"");
        }
    }

    @Override
    public List<String> tasks() {
        return TASKS;
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
        if (!wanted.task().equals("height")) {
            notes.add("the " + wanted.task() + " task is not built yet: showing the height task");
            shown = shown.withTask("height");
        }
        if (wanted.controller().equals("learned")) {
            notes.add(learnedUnavailable() + ": using the nominal controller");
            shown = shown.withController("nominal");
        }
        InteractiveScene scene = new CatchLoopScene(Runtime.simulator(model, simConfig),
                Runtime.nominalEvaluation(shown.object(), Runtime.heightTask(goals)), shown.seed(), heightControl);
        return new Opened(scene, shown, notes);
    }

    /** Why the learned controller cannot be shown (yet). */
    private String learnedUnavailable() {
        if (policy == null) {
            return "no learned policy (give --policy FILE)";
        }
        if (!Files.isRegularFile(policy)) {
            return "learned policy " + policy + " does not exist";
        }
        return "learned policies cannot be loaded yet (issue 3)";
    }
}
