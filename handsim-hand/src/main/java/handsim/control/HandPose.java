package handsim.control;

/** The three predefined hand poses of sec. 3.5. */
public enum HandPose {
    NEUTRAL,
    OPEN,
    CLOSED
}
