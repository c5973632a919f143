package handsim.cards.sleight;

/**
 * The outcome of one Card Snapping trial.
 *
 * @param alphaEnd          angle between the cards' long axes at the end (degrees)
 * @param objective         |α_target − α_end| (degrees), thesis eq. (4.5)
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
 */
public record SnapResult(double alphaEnd, double objective, double minGap, long steps, long newtonIterations,
                         double simulatedSeconds, double wallSeconds, double assemblySeconds, double contactSeconds,
                         double solveSeconds, int maxContacts) {

    public double newtonIterationsPerSimulatedSecond() {
        return newtonIterations / simulatedSeconds;
    }
}
