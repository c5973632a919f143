package handsim.cards.energy;

/**
 * One term of the incremental potential, a sum over elements and a function of all node
 * positions {@code x} (3 per node, SI units, energy in joules). Gradients are added into {@code
 * g}; Hessians go element by element to a {@link HessianSink}, projected to positive
 * semi-definite when {@code project} is set (projected Newton) and exact otherwise
 * (finite-difference checks). The range methods cover elements [from, to) so that assembly can
 * split the work; {@link #workspaceCopy()} gives another thread its own scratch memory.
 */
public interface Energy {

    int elementCount();

    double value(double[] x, int from, int to);

    void addGradient(double[] x, int from, int to, double[] g);

    void addHessian(double[] x, int from, int to, HessianSink sink, boolean project);

    /** Gradient and Hessian in one pass (implementations share the per-element work). */
    default void addGradientAndHessian(double[] x, int from, int to, double[] g, HessianSink sink, boolean project) {
        addGradient(x, from, to, g);
        addHessian(x, from, to, sink, project);
    }

    /** The same energy with its own scratch memory (element data shared). */
    Energy workspaceCopy();

    default double value(double[] x) {
        return value(x, 0, elementCount());
    }

    default void addGradient(double[] x, double[] g) {
        addGradient(x, 0, elementCount(), g);
    }

    default void addHessian(double[] x, HessianSink sink, boolean project) {
        addHessian(x, 0, elementCount(), sink, project);
    }
}
