package handsim.cards.sim;

/**
 * Numerical settings of the card simulator (SI units), read from configs/cards.
 *
 * @param timeStep           implicit Euler step h (s)
 * @param dhat               barrier activation distance beyond the thickness offset (m)
 * @param newtonTolerance    Newton stops when the largest node update over h is below this (m/s)
 * @param maxNewtonIterations cap on Newton iterations per step
 * @param cgTolerance        a Newton system solved by conjugate gradients, preconditioned by an
 *                           earlier factorisation, is solved when the preconditioned residual
 *                           falls below this fraction of its start
 * @param cgMaxIterations    CG iterations before the system is factored afresh (0: factor every
 *                           Newton iteration)
 * @param ccdRescaling       additive CCD's conservative rescaling η
 * @param friction           friction coefficients: card–card, skin on anything, card on the ground
 * @param frictionEpsV       slip speed below which friction is smoothed (m/s)
 * @param kappaScale         IPC's minimum-stiffness scale (1e11 in the IPC Toolkit)
 * @param gravity            gravity (m/s²)
 * @param hashCell           spatial hash cell size (m)
 * @param factorisation      the sparse factorisation of the Newton system
 * @param parallel           assemble and factor on two threads (the result is bit-identical either way)
 * @param gaussNewtonContacts each contact's Hessian is its Gauss–Newton part (positive
 *                           semi-definite without an eigen-decomposition) instead of the projected
 *                           full Hessian ({@link handsim.cards.contact.ContactSet#useGaussNewton})
 */
public record SolverSettings(double timeStep, double dhat, double newtonTolerance, int maxNewtonIterations,
                             double cgTolerance, int cgMaxIterations,
                             double ccdRescaling, handsim.cards.contact.CollisionMesh.FrictionTable friction, double frictionEpsV, double kappaScale,
                             double[] gravity, double hashCell,
                             handsim.cards.linalg.SparseSpdSystem.Factorisation factorisation, boolean parallel,
                             boolean gaussNewtonContacts) {

    public SolverSettings {
        gravity = gravity.clone();
    }

    @Override
    public double[] gravity() {
        return gravity.clone();
    }
}
