package handsim.scene;

/**
 * What to show: a task ({@code height}, {@code box}, {@code flip}), an object
 * ({@code configs/objects/NAME.json}), a controller ({@code nominal}, {@code learned}) and the
 * seed of the first episode.
 */
public record SceneSetup(String task, String object, String controller, long seed) {

    public SceneSetup withTask(String t) {
        return new SceneSetup(t, object, controller, seed);
    }

    public SceneSetup withObject(String o) {
        return new SceneSetup(task, o, controller, seed);
    }

    public SceneSetup withController(String c) {
        return new SceneSetup(task, object, c, seed);
    }

    public SceneSetup withSeed(long s) {
        return new SceneSetup(task, object, controller, s);
    }
}
