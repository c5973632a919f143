package handsim.viewer;

import static org.lwjgl.glfw.GLFW.*;

import handsim.scene.SceneCommand;

/**
 * Everything a key does in the viewer, with its key and the line the help panel shows. Actions
 * with a {@link SceneCommand} go to the scene; the others are the viewer's own (camera, pacing,
 * overlays, pictures).
 */
enum ViewerAction {
    HELP(GLFW_KEY_H, "H", "show / hide this help"),
    PAUSE(GLFW_KEY_SPACE, "Space", "pause / resume"),
    STEP(GLFW_KEY_PERIOD, ".", "single step (pauses)"),
    SLOW_MOTION(GLFW_KEY_S, "S", "slow motion: 1, 1/2, 1/4, 1/10 ×"),
    RESET(GLFW_KEY_R, "R", "reset the episode", SceneCommand.RESET),
    NEW_THROW(GLFW_KEY_N, "N", "throw a new object in", SceneCommand.NEW_THROW),
    NEXT_OBJECT(GLFW_KEY_O, "O", "next object", SceneCommand.NEXT_OBJECT),
    NEXT_TASK(GLFW_KEY_T, "T", "next task", SceneCommand.NEXT_TASK),
    CONTROLLER(GLFW_KEY_C, "C", "nominal ↔ learned controller", SceneCommand.TOGGLE_CONTROLLER),
    GOAL_UP(GLFW_KEY_UP, "↑", "raise the target height (or the box)", SceneCommand.GOAL_UP),
    GOAL_DOWN(GLFW_KEY_DOWN, "↓", "lower the target height (or the box)", SceneCommand.GOAL_DOWN),
    GOAL_LEFT(GLFW_KEY_LEFT, "←", "move the box left", SceneCommand.GOAL_LEFT),
    GOAL_RIGHT(GLFW_KEY_RIGHT, "→", "move the box right", SceneCommand.GOAL_RIGHT),
    GOAL_NEARER(GLFW_KEY_PAGE_DOWN, "PgDn", "move the box nearer", SceneCommand.GOAL_NEARER),
    GOAL_FARTHER(GLFW_KEY_PAGE_UP, "PgUp", "move the box farther", SceneCommand.GOAL_FARTHER),
    FOLLOW(GLFW_KEY_F, "F", "camera follows the object"),
    RESET_CAMERA(GLFW_KEY_V, "V", "reset the camera"),
    TRAIL(GLFW_KEY_P, "P", "object's path (trail)"),
    AXES(GLFW_KEY_J, "J", "joint axes"),
    RECORD(GLFW_KEY_M, "M", "start / stop recording PNG frames"),
    RECORD_GLTF(GLFW_KEY_G, "G", "start / stop recording the animation as glTF (.glb)"),
    SCREENSHOT(GLFW_KEY_I, "I", "screenshot (PNG)"),
    QUIT(GLFW_KEY_ESCAPE, "Esc", "quit");

    /** The GLFW key code. */
    final int key;
    /** The key as the help panel names it. */
    final String label;
    final String description;
    /** The scene command this action sends, or null for the viewer's own actions. */
    final SceneCommand command;

    ViewerAction(int key, String label, String description) {
        this(key, label, description, null);
    }

    ViewerAction(int key, String label, String description, SceneCommand command) {
        this.key = key;
        this.label = label;
        this.description = description;
        this.command = command;
    }

    /** The action bound to GLFW key {@code key}, or null. */
    static ViewerAction forKey(int key) {
        for (ViewerAction a : values()) {
            if (a.key == key) {
                return a;
            }
        }
        return null;
    }

    /** Whether holding the key down repeats the action (goal moves do; toggles do not). */
    boolean repeats() {
        return command != null && command.name().startsWith("GOAL_");
    }
}
