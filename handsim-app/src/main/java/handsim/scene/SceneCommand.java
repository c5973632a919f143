package handsim.scene;

/**
 * What a person watching can ask of an {@link InteractiveScene}. A scene that cannot do a
 * command (moving the box of the height task, say) answers with a note and carries on.
 */
public enum SceneCommand {
    /** Start the current episode again from its seed. */
    RESET,
    /** Throw a new object in (the next seed's launch). */
    NEW_THROW,
    /** Switch to the next object (sphere, can, cuboid, club). */
    NEXT_OBJECT,
    /** Switch to the next task (height, box, flip). */
    NEXT_TASK,
    /** Switch between the nominal and the learned controller. */
    TOGGLE_CONTROLLER,
    /** Raise the goal: the target height, or the box. */
    GOAL_UP,
    /** Lower the goal. */
    GOAL_DOWN,
    /** Move the box toward -x (the person's right). */
    GOAL_LEFT,
    /** Move the box toward +x. */
    GOAL_RIGHT,
    /** Move the box toward the shoulder (-z). */
    GOAL_NEARER,
    /** Move the box away from the shoulder (+z). */
    GOAL_FARTHER
}
