package handsim.cards.contact;

/** Receives node pairs (for the Newton system's sparsity pattern). */
@FunctionalInterface
public interface PairVisitor {

    void accept(int a, int b);
}
