package handsim.scene;

import handsim.task.Goal;

/**
 * A {@link Scene} a person can watch and steer: it describes its goal for drawing and takes
 * {@link SceneCommand}s. A new task or controller becomes watchable by implementing this
 * interface and being offered by a {@link SceneCatalog}; the viewer needs nothing else.
 * Called from one thread only (the one that advances the scene).
 */
public interface InteractiveScene extends Scene {

    /**
     * The {@link #status()} entry that says what is shown instead of what was asked for (a task
     * or controller that is not available); watchers show it as a warning.
     */
    String FALLBACK = "fallback";

    /** The task's goal now, for drawing. */
    Goal goal();

    /**
     * Does {@code command} if this scene can, and returns a one-line note on what happened (for
     * the screen and the log). A command the scene cannot do is answered with a note, never an
     * exception.
     */
    String apply(SceneCommand command);
}
