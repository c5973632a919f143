package handsim.scene;

import handsim.sim.WorldSnapshot;
import handsim.task.Goal;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The scene the viewer talks to: it shows one scene of a {@link SceneCatalog} at a time and
 * switches task, object and controller on command by opening another one (cycling through the
 * catalog's names from what was asked for, so a fallback never traps the cycle); every other command
 * goes to the scene being shown. The status starts with the task, object and controller shown
 * and, while something asked for is not available, a {@link #FALLBACK} entry saying so.
 */
public final class SwitchingScene implements InteractiveScene {

    private final SceneCatalog catalog;
    private final List<String> notes = new ArrayList<>();
    private SceneSetup wanted;
    private SceneSetup shown;
    private InteractiveScene scene;

    /** Opens {@code wanted} (or its fallback: see {@link #openingNotes()}). */
    public SwitchingScene(SceneCatalog catalog, SceneSetup wanted) {
        this.catalog = catalog;
        this.wanted = wanted;
        open(wanted);
    }

    /** What the first {@link SceneCatalog#open} substituted, if anything. */
    public List<String> openingNotes() {
        return List.copyOf(notes);
    }

    /** The setup shown now. */
    public SceneSetup shown() {
        return shown;
    }

    @Override
    public String apply(SceneCommand command) {
        return switch (command) {
            case NEXT_TASK -> switchTo(wanted.withTask(next(catalog.tasks(), wanted.task())));
            case NEXT_OBJECT -> switchTo(wanted.withObject(next(catalog.objects(), wanted.object())));
            case TOGGLE_CONTROLLER -> switchTo(wanted.withController(next(catalog.controllers(), wanted.controller())));
            default -> scene.apply(command);
        };
    }

    private String switchTo(SceneSetup setup) {
        scene.close();
        open(setup);
        wanted = setup;
        String summary = "now: " + shown.task() + " task, " + shown.object() + ", " + shown.controller() + " controller";
        return notes.isEmpty() ? summary : String.join("; ", notes);
    }

    private void open(SceneSetup setup) {
        SceneCatalog.Opened opened = catalog.open(setup);
        scene = opened.scene();
        shown = opened.setup();
        notes.clear();
        notes.addAll(opened.notes());
    }

    private static String next(List<String> names, String current) {
        int i = names.indexOf(current);
        return names.get((i + 1) % names.size());
    }

    @Override
    public Goal goal() {
        return scene.goal();
    }

    @Override
    public void advance(double seconds) {
        scene.advance(seconds);
    }

    @Override
    public double time() {
        return scene.time();
    }

    @Override
    public WorldSnapshot snapshot() {
        return scene.snapshot();
    }

    @Override
    public Map<String, String> status() {
        Map<String, String> s = new LinkedHashMap<>();
        s.put("task", shown.task());
        s.put("object", shown.object());
        s.put("controller", shown.controller());
        if (!notes.isEmpty()) {
            s.put(FALLBACK, String.join("; ", notes));
        }
        s.putAll(scene.status());
        return s;
    }

    @Override
    public void close() {
        scene.close();
    }
}
