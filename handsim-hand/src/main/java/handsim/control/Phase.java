package handsim.control;

/** The four states of the paper's finite state machine (sec. 3.1), in loop order. */
public enum Phase {
    /** The hand opens and moves to meet the object at the interception point. */
    CATCH,
    /** The hand, closed on the object, decelerates to rest at the neutral position. */
    MIDDLE,
    /** The hand throws along the curve set by the throw parameters; it opens at t_open. */
    THROW,
    /** The hand returns to the rest plane, ready for the next catch. */
    GOBACK;

    public Phase next() {
        return values()[(ordinal() + 1) % values().length];
    }
}
