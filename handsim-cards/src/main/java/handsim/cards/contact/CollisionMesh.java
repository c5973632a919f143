package handsim.cards.contact;

/**
 * What can touch: contact vertices, edges and faces (global node indices), the body of each
 * node, each body's half thickness (the offset ξ of a pair is the sum of its two bodies'; cards
 * have half their thickness, fingertips none) and whether a body may touch itself. Cards are
 * codimensional shells and contribute all their vertices, edges and triangles; a fingertip its
 * boundary surface. An optional static ground plane z = height touches every contact vertex.
 */
public final class CollisionMesh {

    final int[] vertices;
    final int[] edges;
    final int[] faces;
    final int[] bodyOfNode;
    final double[] halfThickness;
    final boolean[] selfContact;
    final double[] rest;
    final boolean[] isCard;
    final FrictionTable friction;
    final boolean hasGround;
    final double groundHeight;
    /** per node: held in place (a bone or a fixed card), so a pair of only such nodes never changes */
    final boolean[] fixedNode;

    /**
     * @param vertices      contact vertices (node indices)
     * @param edges         node pairs
     * @param faces         node triples
     * @param bodyOfNode    body index of every node
     * @param halfThickness per body (m)
     * @param selfContact   per body
     * @param rest          rest positions of all nodes (for the edge–edge mollifier threshold)
     * @param isCard        per body: a card (else a fingertip)
     * @param friction      friction coefficients by pair kind
     * @param groundHeight  height of the static ground plane (m), or NaN for none
     * @param fixedNode     per node: whether it is held in place; pairs of held primitives are
     *                      left out (their barrier is constant), or null when every node moves
     */
    public CollisionMesh(int[] vertices, int[] edges, int[] faces, int[] bodyOfNode, double[] halfThickness,
                         boolean[] selfContact, double[] rest, boolean[] isCard, FrictionTable friction,
                         double groundHeight, boolean[] fixedNode) {
        if (bodyOfNode.length >= 1 << 15) {
            throw new IllegalArgumentException("contact keys hold node indices below 32768, got " + bodyOfNode.length + " nodes");
        }
        this.vertices = vertices.clone();
        this.edges = edges.clone();
        this.faces = faces.clone();
        this.bodyOfNode = bodyOfNode.clone();
        this.halfThickness = halfThickness.clone();
        this.selfContact = selfContact.clone();
        this.rest = rest.clone();
        this.isCard = isCard.clone();
        this.friction = friction;
        this.hasGround = !Double.isNaN(groundHeight);
        this.groundHeight = groundHeight;
        this.fixedNode = fixedNode == null ? new boolean[bodyOfNode.length] : fixedNode.clone();
    }

    /** Whether nodes a and b are both held in place. */
    boolean fixed(int a, int b) {
        return fixedNode[a] && fixedNode[b];
    }

    /** Whether nodes a, b and c are all held in place. */
    boolean fixed(int a, int b, int c) {
        return fixedNode[a] && fixedNode[b] && fixedNode[c];
    }

    public int vertexCount() {
        return vertices.length;
    }

    public int edgeCount() {
        return edges.length / 2;
    }

    public int faceCount() {
        return faces.length / 3;
    }

    /** Friction coefficients by pair kind: card–card, anything touching skin, a card on the ground. */
    public record FrictionTable(double cardCard, double skin, double ground) {
    }

    /** μ between the bodies of two nodes. */
    double frictionBetween(int nodeA, int nodeB) {
        boolean a = isCard[bodyOfNode[nodeA]];
        boolean b = isCard[bodyOfNode[nodeB]];
        return a && b ? friction.cardCard() : friction.skin();
    }

    /** μ between a node's body and the ground. */
    double groundFriction(int node) {
        return isCard[bodyOfNode[node]] ? friction.ground() : friction.skin();
    }

    double offset(int nodeA, int nodeB) {
        return halfThickness[bodyOfNode[nodeA]] + halfThickness[bodyOfNode[nodeB]];
    }

    /** Whether primitives with these first nodes' bodies may touch. */
    boolean bodiesMayTouch(int nodeA, int nodeB) {
        int a = bodyOfNode[nodeA];
        int b = bodyOfNode[nodeB];
        return a != b || selfContact[a];
    }

    /** Largest offset of any pair, ground included (the ground has none of its own). */
    double maxOffset() {
        double m = 0;
        for (double h : halfThickness) {
            m = Math.max(m, h);
        }
        return 2 * m;
    }

    /** The offset IPC's stiffness heuristics use: the largest pair offset in the scene (m). */
    public double maxOffsetForStiffness() {
        return maxOffset();
    }

    public boolean hasGround() {
        return hasGround;
    }

    public double groundHeight() {
        return groundHeight;
    }
}
