package handsim.cards.sleight;

/**
 * The outcome of one Card Snapping trial.
 *
 * @param alphaEnd          angle between the cards' long axes at the end (degrees)
 * @param objective         |α_target − α_end| (degrees), thesis eq. (4.5), for held cards; the
 *                          configured dropped objective (180°) when a card fell
 * @param minGap            smallest gap d − ξ over every step of the trial (m); positive means
 *                          no interpenetration
 * @param steps             time steps of the trial
 * @param newtonIterations  Newton iterations of the trial
 * @param simulatedSeconds  simulated time of the trial (s)
 * @param wallSeconds       wall time of the trial, warm-up excluded (s)
 * @param assemblySeconds   of which energies, gradients and Hessians
 * @param contactSeconds    of which contact detection, barrier evaluation and CCD
 * @param solveSeconds      of which sparse factorisation and solve
 * @param maxContacts       most active contacts at a step end
 * @param cardDrop          how far the lower-lying card's centroid ends below where the hold
 *                          left it (m): millimetres while the fingers hold the cards, far more
 *                          once they let go
 * @param held              the cards ended within the drop limit of the hold
 */
public record SnapResult(double alphaEnd, double objective, double minGap, long steps, long newtonIterations,
                         double simulatedSeconds, double wallSeconds, double assemblySeconds, double contactSeconds,
                         double solveSeconds, int maxContacts, double cardDrop, boolean held) {

    public double newtonIterationsPerSimulatedSecond() {
        return newtonIterations / simulatedSeconds;
    }
}
