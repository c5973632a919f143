package handsim.cards.sleight;

/**
 * The outcome of one Card Snapping trial.
 *
 * @param alphaEnd  angle between the cards' long axes at the end (degrees)
 * @param objective |α_target − α_end| (degrees), thesis eq. (4.5), for held cards; the
 *                  configured dropped objective (180°) when a card fell
 * @param cardDrop  how far the lower-lying card's centroid ends below where the hold left it (m):
 *                  millimetres while the fingers hold the cards, far more once they let go
 * @param held      the cards ended within the drop limit of the hold
 * @param cost      the smallest gap over the run, Newton iterations and the time split
 */
public record SnapResult(double alphaEnd, double objective, double cardDrop, boolean held, TrialCost cost) {

    /** Smallest gap d − ξ over every step of the trial (m); positive means no interpenetration. */
    public double minGap() {
        return cost.minGap();
    }

    public long steps() {
        return cost.steps();
    }

    public long newtonIterations() {
        return cost.newtonIterations();
    }

    public double wallSeconds() {
        return cost.wallSeconds();
    }

    public double newtonIterationsPerSimulatedSecond() {
        return cost.newtonIterations() / cost.simulatedSeconds();
    }
}
