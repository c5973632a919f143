package handsim.scene;

import java.util.List;

/**
 * The scenes handsim can show. {@link #open} builds the scene closest to what was asked: a task
 * or controller that is not available (not built yet, no policy file) falls back to one that is,
 * and the notes say what was substituted and why.
 */
public interface SceneCatalog {

    /** A scene and the setup it really shows. */
    record Opened(InteractiveScene scene, SceneSetup setup, List<String> notes) {
        public Opened {
            notes = List.copyOf(notes);
        }
    }

    /** Task names, in the order the viewer cycles through them (available or not). */
    List<String> tasks();

    /** Object names, in cycling order. */
    List<String> objects();

    /** Controller names, in cycling order. */
    List<String> controllers();

    /** Opens {@code wanted}, or the nearest available setup; never fails for a name it lists. */
    Opened open(SceneSetup wanted);
}
