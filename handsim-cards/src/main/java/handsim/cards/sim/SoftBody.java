package handsim.cards.sim;

/**
 * One body of a card scene: a card (thin shell) or a fingertip (tetrahedral solid). Its nodes are
 * the contiguous range [firstNode, firstNode + nodeCount) of the world; {@code surface} holds its
 * outward (for a card, upward) triangles in world node indices, for drawing; {@code thickness}
 * is a card's shell thickness (m), 0 for a fingertip.
 */
public record SoftBody(String name, Kind kind, int firstNode, int nodeCount, int[] surface, double thickness) {

    public enum Kind { CARD, FINGERTIP }

    public SoftBody {
        surface = surface.clone();
    }

    @Override
    public int[] surface() {
        return surface.clone();
    }

    public boolean contains(int node) {
        return node >= firstNode && node < firstNode + nodeCount;
    }
}
