package handsim.cards.energy;

/**
 * One term of the incremental potential, a function of all node positions {@code x} (3 per node,
 * SI units, energy in joules). Gradients are added into {@code g}; Hessians go element by element
 * to a {@link HessianSink}, projected to positive semi-definite when {@code project} is set
 * (projected Newton) and exact otherwise (finite-difference checks).
 */
public interface Energy {

    double value(double[] x);

    void addGradient(double[] x, double[] g);

    void addHessian(double[] x, HessianSink sink, boolean project);
}
