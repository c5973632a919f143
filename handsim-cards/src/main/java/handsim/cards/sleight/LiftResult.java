package handsim.cards.sleight;

/**
 * The outcome of one Double Lift trial (thesis eq. 4.6).
 *
 * @param h1      how far the top card's centroid rose (m)
 * @param h2      how far the second card's centroid rose (m)
 * @param h3      how far the third card's centroid rose (m)
 * @param d3      how far the third card's centroid moved (m)
 * @param hTarget the rise the top two should end at (m)
 * @param cost    the smallest gap over the run, Newton iterations and the time split
 */
public record LiftResult(double h1, double h2, double h3, double d3, double hTarget, TrialCost cost) {

    /** (|h1 − h_target|, |h2 − h_target|, ‖d3‖) in metres, all minimised. */
    public double[] values() {
        return new double[] {Math.abs(h1 - hTarget), Math.abs(h2 - hTarget), d3};
    }
}
