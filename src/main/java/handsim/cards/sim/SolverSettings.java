package handsim.cards.sim;

/**
 * Numerical settings of the card simulator (SI units), read from configs/cards.
 *
 * @param timeStep           implicit Euler step h (s)
 * @param dhat               barrier activation distance beyond the thickness offset (m)
 * @param newtonTolerance    Newton stops when the largest node update over h is below this (m/s)
 * @param maxNewtonIterations cap on Newton iterations per step
 * @param ccdRescaling       additive CCD's conservative rescaling η
 * @param friction           friction coefficients: card–card, skin on anything, card on the ground
 * @param frictionEpsV       slip speed below which friction is smoothed (m/s)
 * @param kappaScale         IPC's minimum-stiffness scale (1e11 in the IPC Toolkit)
 * @param gravity            gravity (m/s²)
 * @param hashCell           spatial hash cell size (m)
 * @param parallelAssembly   assemble on two threads (the result is bit-identical either way)
 */
public record SolverSettings(double timeStep, double dhat, double newtonTolerance, int maxNewtonIterations,
                             double ccdRescaling, handsim.cards.contact.CollisionMesh.FrictionTable friction, double frictionEpsV, double kappaScale,
                             double[] gravity, double hashCell, boolean parallelAssembly) {

    public SolverSettings {
        gravity = gravity.clone();
    }

    @Override
    public double[] gravity() {
        return gravity.clone();
    }
}
