package handsim.cards.sim;

/**
 * What the simulator spent, accumulated over steps: Newton iterations, line-search halvings,
 * symbolic rebuilds of the Newton system, and wall time (nanoseconds) split into assembly
 * (energies, gradients, Hessians), contact (broad and narrow phase, CCD) and solve (sparse
 * factorisation and substitution). {@code minGap} is the smallest gap d − ξ seen (m).
 */
public final class StepStats {

    public long steps;
    public long newtonIterations;
    public long lineSearchHalvings;
    public long unconvergedSteps;
    public long patternBuilds;
    /** numeric factorisations of the Newton system, and those that needed a diagonal shift to find positive pivots */
    public long factorisations;
    public long shiftedFactorisations;
    /** conjugate-gradient iterations of Newton solves preconditioned by an earlier factorisation */
    public long cgIterations;
    public long assemblyNanos;
    public long contactNanos;
    public long solveNanos;
    public int maxContacts;
    public double minGap = Double.POSITIVE_INFINITY;

    public void add(StepStats o) {
        steps += o.steps;
        newtonIterations += o.newtonIterations;
        lineSearchHalvings += o.lineSearchHalvings;
        unconvergedSteps += o.unconvergedSteps;
        patternBuilds += o.patternBuilds;
        factorisations += o.factorisations;
        shiftedFactorisations += o.shiftedFactorisations;
        cgIterations += o.cgIterations;
        assemblyNanos += o.assemblyNanos;
        contactNanos += o.contactNanos;
        solveNanos += o.solveNanos;
        maxContacts = Math.max(maxContacts, o.maxContacts);
        minGap = Math.min(minGap, o.minGap);
    }
}
