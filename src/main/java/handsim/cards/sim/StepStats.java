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
    /** factorisations that needed a diagonal shift to find positive pivots */
    public long shiftedFactorisations;
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
        shiftedFactorisations += o.shiftedFactorisations;
        assemblyNanos += o.assemblyNanos;
        contactNanos += o.contactNanos;
        solveNanos += o.solveNanos;
        maxContacts = Math.max(maxContacts, o.maxContacts);
        minGap = Math.min(minGap, o.minGap);
    }
}
