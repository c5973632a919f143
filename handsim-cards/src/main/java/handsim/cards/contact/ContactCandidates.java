package handsim.cards.contact;

import handsim.cards.geom.AdditiveCcd;
import java.util.Arrays;

/**
 * The broad phase of the contacts: candidate pairs from two {@link SpatialHash}es, vertices
 * against faces and edges against edges, whose boxes over a motion come within a radius; and the
 * additive CCD over those swept boxes ({@link #largestSafeStep}), which keeps every Newton update
 * intersection-free.
 */
final class ContactCandidates {

    private final CollisionMesh mesh;
    private final SpatialHash vertexHash;
    private final SpatialHash edgeHash;

    // candidate pairs of the last query: (face, vertex) and (edge, edge)
    int ptCount;
    int[] ptPairs = new int[512];
    int eeCount;
    int[] eePairs = new int[512];

    /** The most candidate pairs one query may find: a memory budget (8 bytes each, and their contacts' more). */
    private long maxPairs = Integer.MAX_VALUE / 2 - 8;

    // workspace
    private double[] vertexBoxes = new double[0];
    private double[] edgeBoxes = new double[0];
    private double[] sweepEnd = new double[0];

    ContactCandidates(CollisionMesh mesh, double cellSize) {
        this.mesh = mesh;
        this.vertexHash = new SpatialHash(cellSize);
        this.edgeHash = new SpatialHash(cellSize);
    }

    /** Sets the memory budgets: (cell, id) entries per spatial hash and candidate pairs per query ({@link BudgetExceeded} past them). */
    void limit(long hashEntries, long pairs) {
        vertexHash.limit(hashEntries);
        edgeHash.limit(hashEntries);
        maxPairs = Math.min(pairs, Integer.MAX_VALUE / 2 - 8);
    }

    /** Makes room for one more pair in {@code pairs} (two ints each), within the budget. */
    private int[] roomForPair(int[] pairs, int count) {
        if ((long) ptCount + eeCount >= maxPairs) {
            throw new BudgetExceeded("more than " + maxPairs + " candidate contact pairs (configs/cards/budget.json maxContactPairs): "
                    + "the bodies crowd together, or sweep through each other, far past a card scene's contacts");
        }
        return 2 * count + 2 > pairs.length ? Arrays.copyOf(pairs, 2 * pairs.length) : pairs;
    }

    /**
     * Candidate pairs whose boxes, over the motion from x0 to x1 (x1 may be null for a static
     * query), come within {@code radius}.
     */
    void find(double[] x0, double[] x1, double radius) {
        int nv = mesh.vertices.length;
        int ne = mesh.edges.length / 2;
        if (vertexBoxes.length < 6 * nv) {
            vertexBoxes = new double[6 * nv];
        }
        if (edgeBoxes.length < 6 * ne) {
            edgeBoxes = new double[6 * ne];
        }
        for (int i = 0; i < nv; i++) {
            box(x0, x1, mesh.vertices, i, 1, vertexBoxes, i, 0);
        }
        for (int e = 0; e < ne; e++) {
            box(x0, x1, mesh.edges, e, 2, edgeBoxes, e, radius);
        }
        vertexHash.build(vertexBoxes, nv);
        edgeHash.build(edgeBoxes, ne);
        ptCount = 0;
        eeCount = 0;
        double[] fb = new double[6];
        int nf = mesh.faces.length / 3;
        for (int f = 0; f < nf; f++) {
            box(x0, x1, mesh.faces, f, 3, fb, 0, radius);
            final int face = f;
            int f0 = mesh.faces[3 * f];
            int f1 = mesh.faces[3 * f + 1];
            int f2 = mesh.faces[3 * f + 2];
            boolean faceFixed = mesh.fixed(f0, f1, f2);
            vertexHash.query(fb[0], fb[1], fb[2], fb[3], fb[4], fb[5], v -> {
                int p = mesh.vertices[v];
                if (p == f0 || p == f1 || p == f2 || !mesh.bodiesMayTouch(p, f0) || (faceFixed && mesh.fixedNode[p])
                        || !overlaps(vertexBoxes, v, fb)) {
                    return;
                }
                ptPairs = roomForPair(ptPairs, ptCount);
                ptPairs[2 * ptCount] = face;
                ptPairs[2 * ptCount + 1] = p;
                ptCount++;
            });
        }
        eeCount = 0;
        for (int e = 0; e < ne; e++) {
            final int edge = e;
            int a0 = mesh.edges[2 * e];
            int a1 = mesh.edges[2 * e + 1];
            if (mesh.fixed(a0, a1)) {
                continue; // a held edge meets moving ones from their side
            }
            edgeHash.query(edgeBoxes[6 * e], edgeBoxes[6 * e + 1], edgeBoxes[6 * e + 2],
                    edgeBoxes[6 * e + 3], edgeBoxes[6 * e + 4], edgeBoxes[6 * e + 5], other -> {
                    int b0 = mesh.edges[2 * other];
                    int b1 = mesh.edges[2 * other + 1];
                    // each pair once: from its lower edge, or from its moving edge when the other is held
                    if (other == edge || (other < edge && !mesh.fixed(b0, b1))) {
                        return;
                    }
                    if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1 || !mesh.bodiesMayTouch(a0, b0)) {
                        return;
                    }
                    // both boxes carry the radius; require overlap of one inflated box with the other's core
                    if (!boxesOverlap(edgeBoxes, edge, edgeBoxes, other, radius)) {
                        return;
                    }
                    eePairs = roomForPair(eePairs, eeCount);
                    eePairs[2 * eeCount] = edge;
                    eePairs[2 * eeCount + 1] = other;
                    eeCount++;
                });
        }
    }

    /** Box of primitive {@code i} (k nodes of {@code prims}) over x0 and x1, grown by {@code grow}. */
    private static void box(double[] x0, double[] x1, int[] prims, int i, int k, double[] out, int slot, double grow) {
        double minX = Double.POSITIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double minZ = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        double maxZ = Double.NEGATIVE_INFINITY;
        for (int s = 0; s < k; s++) {
            int n = 3 * prims[k * i + s];
            for (int pass = 0; pass < (x1 == null ? 1 : 2); pass++) {
                double[] x = pass == 0 ? x0 : x1;
                minX = Math.min(minX, x[n]);
                minY = Math.min(minY, x[n + 1]);
                minZ = Math.min(minZ, x[n + 2]);
                maxX = Math.max(maxX, x[n]);
                maxY = Math.max(maxY, x[n + 1]);
                maxZ = Math.max(maxZ, x[n + 2]);
            }
        }
        int o = 6 * slot;
        out[o] = minX - grow;
        out[o + 1] = minY - grow;
        out[o + 2] = minZ - grow;
        out[o + 3] = maxX + grow;
        out[o + 4] = maxY + grow;
        out[o + 5] = maxZ + grow;
    }

    private static boolean overlaps(double[] boxes, int i, double[] b) {
        int o = 6 * i;
        return boxes[o] <= b[3] && boxes[o + 3] >= b[0] && boxes[o + 1] <= b[4] && boxes[o + 4] >= b[1]
                && boxes[o + 2] <= b[5] && boxes[o + 5] >= b[2];
    }

    /** Overlap of two boxes that each carry {@code grow}: their cores within grow of each other. */
    private static boolean boxesOverlap(double[] a, int i, double[] b, int j, double grow) {
        int p = 6 * i;
        int q = 6 * j;
        for (int c = 0; c < 3; c++) {
            if (a[p + c] + grow > b[q + 3 + c] || b[q + c] + grow > a[p + 3 + c]) {
                return false;
            }
        }
        return true;
    }

    /**
     * The largest fraction α ≤ 1 of the update p such that the motion from x to x + α p keeps every
     * pair apart by more than its offset, by additive CCD with rescaling η (Codim-IPC uses 0.9).
     * Its candidates, the pairs whose swept boxes come within {@code radius}, stay for the next
     * {@link ContactSet#buildAlongSweep}.
     */
    double largestSafeStep(double[] x, double[] p, double eta, double radius) {
        int n = x.length;
        if (sweepEnd.length != n) {
            sweepEnd = new double[n];
        }
        double[] x1 = sweepEnd;
        for (int i = 0; i < n; i++) {
            x1[i] = x[i] + p[i];
        }
        find(x, x1, radius);
        double alpha = 1;
        double[] a0 = new double[12];
        double[] a1 = new double[12];
        for (int k = 0; k < ptCount; k++) {
            int f = ptPairs[2 * k];
            int v = ptPairs[2 * k + 1];
            int t0 = mesh.faces[3 * f];
            int t1 = mesh.faces[3 * f + 1];
            int t2 = mesh.faces[3 * f + 2];
            ContactSet.gather(x, a0, v, t0, t1, t2);
            ContactSet.gather(x1, a1, v, t0, t1, t2);
            double toi = AdditiveCcd.pointTriangle(a0, a1, mesh.offset(v, t0), eta, alpha);
            alpha = Math.min(alpha, toi);
        }
        for (int k = 0; k < eeCount; k++) {
            int ea = eePairs[2 * k];
            int eb = eePairs[2 * k + 1];
            int p0 = mesh.edges[2 * ea];
            int p1 = mesh.edges[2 * ea + 1];
            int q0 = mesh.edges[2 * eb];
            int q1 = mesh.edges[2 * eb + 1];
            ContactSet.gather(x, a0, p0, p1, q0, q1);
            ContactSet.gather(x1, a1, p0, p1, q0, q1);
            double toi = AdditiveCcd.edgeEdge(a0, a1, mesh.offset(p0, q0), eta, alpha);
            alpha = Math.min(alpha, toi);
        }
        if (mesh.hasGround) {
            for (int v = 0; v < mesh.vertices.length; v++) {
                if (mesh.fixedNode[mesh.vertices[v]]) {
                    continue;
                }
                int q = 3 * mesh.vertices[v] + 2;
                double dz = p[q];
                if (dz < 0) {
                    double offset = mesh.halfThickness[mesh.bodyOfNode[mesh.vertices[v]]];
                    double gap = x[q] - mesh.groundHeight - offset;
                    alpha = Math.min(alpha, eta * gap / -dz);
                }
            }
        }
        return alpha;
    }
}
