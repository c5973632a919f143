package handsim.cards.tpe;

/** Whether an objective is minimised or maximised. */
public enum Direction {
    MINIMIZE, MAXIMIZE;

    /** The value as a loss (smaller is better): maximised objectives change sign. */
    double loss(double value) {
        return this == MAXIMIZE ? -value : value;
    }
}
