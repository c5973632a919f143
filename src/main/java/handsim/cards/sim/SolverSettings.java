package handsim.cards.sim;

/**
 * Numerical settings of the card simulator (SI units), read from configs/cards.
 *
 * @param timeStep           implicit Euler step h (s)
 * @param dhat               barrier activation distance beyond the thickness offset (m)
 * @param newtonTolerance    Newton stops when the largest node update over h is below this (m/s)
 * @param maxNewtonIterations cap on Newton iterations per step
 * @param ccdRescaling       additive CCD's conservative rescaling η
 * @param friction           friction coefficient μ of every contact
 * @param frictionEpsV       slip speed below which friction is smoothed (m/s)
 * @param kappaScale         IPC's minimum-stiffness scale (1e11 in the IPC Toolkit)
 * @param gravity            gravity (m/s²)
 * @param hashCell           spatial hash cell size (m)
 */
public record SolverSettings(double timeStep, double dhat, double newtonTolerance, int maxNewtonIterations,
                             double ccdRescaling, double friction, double frictionEpsV, double kappaScale,
                             double[] gravity, double hashCell) {

    public SolverSettings {
        gravity = gravity.clone();
    }

    @Override
    public double[] gravity() {
        return gravity.clone();
    }
}
