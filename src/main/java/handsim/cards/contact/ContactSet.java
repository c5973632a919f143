package handsim.cards.contact;

import handsim.cards.energy.HessianSink;
import handsim.cards.geom.AdditiveCcd;
import handsim.cards.geom.DistanceType;
import handsim.cards.geom.DistanceTypes;
import handsim.cards.geom.Distances;
import handsim.cards.geom.EdgeEdgeMollifier;
import handsim.cards.linalg.SymmetricEigen;
import java.util.Arrays;

/**
 * The active contacts of IPC at one configuration and their barrier (Li et al. 2020, eq. 6):
 * κ Σ m_k b(d_k² − ξ_k², ŝ_k) over primitive pairs within the activation distance d̂ of their
 * thickness offset ξ_k (ŝ = (ξ + d̂)² − ξ²; m_k the edge–edge mollifier, 1 otherwise).
 *
 * <p>Candidates come from a {@link SpatialHash} (vertices against faces, edges against edges);
 * each close pair is reduced to its closest features (vertex–vertex, edge–vertex, face–vertex,
 * edge–edge, and vertex–ground) and duplicates, such as the edge–vertex pair reached from both
 * faces of the edge, are merged by sorting their keys, which also fixes a deterministic order.
 * Nearly parallel edge pairs keep their edge–edge stencil with the mollifier.
 *
 * <p>The same broad phase over swept boxes feeds {@link #largestSafeStep}, the additive CCD that
 * keeps every Newton update intersection-free.
 */
public final class ContactSet {

    static final int VV = 0;
    static final int EV = 1;
    static final int FV = 2;
    static final int EE = 3;
    static final int GROUND = 4;
    private static final int[] NODES_OF_KIND = {2, 3, 4, 4, 1};

    private final CollisionMesh mesh;
    private final double dhat;
    private final SpatialHash vertexHash;
    private final SpatialHash edgeHash;

    // active contacts (parallel arrays, sorted by key)
    int count;
    int[] kind = new int[256];
    int[] nodes = new int[4 * 256];
    double[] xi = new double[256];
    double[] epsX = new double[256];
    DistanceType[] mollified = new DistanceType[256];
    private long[] keys = new long[256];
    private int[] order = new int[256];

    // candidate pairs of the last broad phase
    private int ptCount;
    private int[] ptPairs = new int[512];
    private int eeCount;
    private int[] eePairs = new int[512];

    // workspace
    private double[] vertexBoxes = new double[0];
    private double[] edgeBoxes = new double[0];
    private final double[] buf = new double[12];
    private final double[] buf2 = new double[12];
    private final Scratch scratch = new Scratch();

    /** Scratch memory of one thread evaluating barrier terms. */
    public static final class Scratch {
        final double[] pos = new double[12];
        final double[] gradD = new double[12];
        final double[] hessD = new double[144];
        final double[] gradM = new double[12];
        final double[] hessM = new double[144];
        final double[] local = new double[144];
        final int[] localNodes = new int[4];
        final SymmetricEigen eigen = new SymmetricEigen(12);
    }

    /**
     * @param mesh     what can touch
     * @param dhat     barrier activation distance d̂ beyond the offset (m)
     * @param cellSize spatial hash cell (m), about the mean contact edge length
     */
    public ContactSet(CollisionMesh mesh, double dhat, double cellSize) {
        this.mesh = mesh;
        this.dhat = dhat;
        this.vertexHash = new SpatialHash(cellSize);
        this.edgeHash = new SpatialHash(cellSize);
    }

    public int size() {
        return count;
    }

    public double dhat() {
        return dhat;
    }

    CollisionMesh mesh() {
        return mesh;
    }

    /** ŝ for offset ξ: the barrier acts while d² − ξ² is below it. */
    double activation(double offset) {
        return 2 * offset * dhat + dhat * dhat;
    }

    // ---- broad phase ---------------------------------------------------------------------------

    /**
     * Candidate pairs whose boxes, over the motion from x0 to x1 (x1 may be null for a static
     * query), come within {@code radius}.
     */
    private void candidates(double[] x0, double[] x1, double radius) {
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
        double[] fb = new double[6];
        int nf = mesh.faces.length / 3;
        for (int f = 0; f < nf; f++) {
            box(x0, x1, mesh.faces, f, 3, fb, 0, radius);
            final int face = f;
            int f0 = mesh.faces[3 * f];
            int f1 = mesh.faces[3 * f + 1];
            int f2 = mesh.faces[3 * f + 2];
            vertexHash.query(fb[0], fb[1], fb[2], fb[3], fb[4], fb[5], v -> {
                int p = mesh.vertices[v];
                if (p == f0 || p == f1 || p == f2 || !mesh.bodiesMayTouch(p, f0) || !overlaps(vertexBoxes, v, fb)) {
                    return;
                }
                if (2 * ptCount + 2 > ptPairs.length) {
                    ptPairs = Arrays.copyOf(ptPairs, 2 * ptPairs.length);
                }
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
            edgeHash.query(edgeBoxes[6 * e], edgeBoxes[6 * e + 1], edgeBoxes[6 * e + 2],
                    edgeBoxes[6 * e + 3], edgeBoxes[6 * e + 4], edgeBoxes[6 * e + 5], other -> {
                    if (other <= edge) {
                        return;
                    }
                    int b0 = mesh.edges[2 * other];
                    int b1 = mesh.edges[2 * other + 1];
                    if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1 || !mesh.bodiesMayTouch(a0, b0)) {
                        return;
                    }
                    // both boxes carry the radius; require overlap of one inflated box with the other's core
                    if (!boxesOverlap(edgeBoxes, edge, edgeBoxes, other, radius)) {
                        return;
                    }
                    if (2 * eeCount + 2 > eePairs.length) {
                        eePairs = Arrays.copyOf(eePairs, 2 * eePairs.length);
                    }
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

    // ---- narrow phase --------------------------------------------------------------------------

    /** Finds the barrier-active contacts at x. */
    public void build(double[] x) {
        double radius = mesh.maxOffset() + dhat;
        candidates(x, null, radius);
        count = 0;
        for (int k = 0; k < ptCount; k++) {
            int f = ptPairs[2 * k];
            int p = ptPairs[2 * k + 1];
            int t0 = mesh.faces[3 * f];
            int t1 = mesh.faces[3 * f + 1];
            int t2 = mesh.faces[3 * f + 2];
            gather(x, buf, p, t0, t1, t2);
            double offset = mesh.offset(p, t0);
            double d2 = Distances.pointTriangle(buf, null, null);
            if (d2 - offset * offset >= activation(offset)) {
                continue;
            }
            DistanceType type = DistanceTypes.pointTriangle(buf);
            int[] st = {p, t0, t1, t2};
            switch (type.kernel()) {
                case POINT_POINT -> add(VV, offset, 0, null, st[type.vertex(0)], st[type.vertex(1)]);
                case POINT_LINE -> add(EV, offset, 0, null, p, st[type.vertex(1)], st[type.vertex(2)]);
                default -> add(FV, offset, 0, null, p, t0, t1, t2);
            }
        }
        for (int k = 0; k < eeCount; k++) {
            int ea = eePairs[2 * k];
            int eb = eePairs[2 * k + 1];
            int[] st = {mesh.edges[2 * ea], mesh.edges[2 * ea + 1], mesh.edges[2 * eb], mesh.edges[2 * eb + 1]};
            gather(x, buf, st[0], st[1], st[2], st[3]);
            double offset = mesh.offset(st[0], st[2]);
            double d2 = Distances.edgeEdge(buf, null, null);
            if (d2 - offset * offset >= activation(offset)) {
                continue;
            }
            DistanceType type = DistanceTypes.edgeEdge(buf);
            gather(mesh.rest, buf2, st[0], st[1], st[2], st[3]);
            double eps = EdgeEdgeMollifier.threshold(buf2);
            double c = EdgeEdgeMollifier.evaluate(buf, eps, null, null);
            if (c < 1) {
                add(EE, offset, eps, type, st[0], st[1], st[2], st[3]);
                continue;
            }
            switch (type.kernel()) {
                case POINT_POINT -> add(VV, offset, 0, null, st[type.vertex(0)], st[type.vertex(1)]);
                case POINT_LINE -> add(EV, offset, 0, null, st[type.vertex(0)], st[type.vertex(1)], st[type.vertex(2)]);
                default -> add(EE, offset, eps, null, st[0], st[1], st[2], st[3]);
            }
        }
        if (mesh.hasGround) {
            for (int v = 0; v < mesh.vertices.length; v++) {
                int p = mesh.vertices[v];
                double offset = mesh.halfThickness[mesh.bodyOfNode[p]];
                double d = x[3 * p + 2] - mesh.groundHeight;
                if (d * d - offset * offset < activation(offset)) {
                    add(GROUND, offset, 0, null, p);
                }
            }
        }
        deduplicate();
    }

    private static void gather(double[] x, double[] out, int... ns) {
        for (int i = 0; i < ns.length; i++) {
            out[3 * i] = x[3 * ns[i]];
            out[3 * i + 1] = x[3 * ns[i] + 1];
            out[3 * i + 2] = x[3 * ns[i] + 2];
        }
    }

    private void add(int k, double offset, double eps, DistanceType molly, int... ns) {
        if (count == kind.length) {
            int cap = 2 * count;
            kind = Arrays.copyOf(kind, cap);
            nodes = Arrays.copyOf(nodes, 4 * cap);
            xi = Arrays.copyOf(xi, cap);
            epsX = Arrays.copyOf(epsX, cap);
            mollified = Arrays.copyOf(mollified, cap);
            keys = Arrays.copyOf(keys, cap);
            order = Arrays.copyOf(order, cap);
        }
        // canonical node order: sorted edges, so duplicates get equal keys
        int[] c = ns.clone();
        if (k == VV && c[0] > c[1]) {
            swap(c, 0, 1);
        } else if (k == EV && c[1] > c[2]) {
            swap(c, 1, 2);
        } else if (k == EE) {
            if (c[0] > c[1]) {
                swap(c, 0, 1);
                molly = molly == null ? null : swapEdgeA(molly);
            }
            if (c[2] > c[3]) {
                swap(c, 2, 3);
                molly = molly == null ? null : swapEdgeB(molly);
            }
            if (c[0] > c[2]) {
                swap(c, 0, 2);
                swap(c, 1, 3);
                molly = molly == null ? null : swapEdges(molly);
            }
        }
        kind[count] = k;
        for (int i = 0; i < 4; i++) {
            nodes[4 * count + i] = i < c.length ? c[i] : -1;
        }
        xi[count] = offset;
        epsX[count] = eps;
        mollified[count] = molly;
        // kind in the top bits, then up to four 15-bit node indices
        long key = (long) k << 60;
        for (int i = 0; i < c.length; i++) {
            key |= (long) c[i] << (45 - 15 * i);
        }
        keys[count] = key;
        count++;
    }

    private static void swap(int[] a, int i, int j) {
        int t = a[i];
        a[i] = a[j];
        a[j] = t;
    }

    private static DistanceType swapEdgeA(DistanceType t) {
        return switch (t) {
            case EE_EA0_EB0 -> DistanceType.EE_EA1_EB0;
            case EE_EA0_EB1 -> DistanceType.EE_EA1_EB1;
            case EE_EA1_EB0 -> DistanceType.EE_EA0_EB0;
            case EE_EA1_EB1 -> DistanceType.EE_EA0_EB1;
            case EE_EA0_EB -> DistanceType.EE_EA1_EB;
            case EE_EA1_EB -> DistanceType.EE_EA0_EB;
            default -> t;
        };
    }

    private static DistanceType swapEdgeB(DistanceType t) {
        return switch (t) {
            case EE_EA0_EB0 -> DistanceType.EE_EA0_EB1;
            case EE_EA0_EB1 -> DistanceType.EE_EA0_EB0;
            case EE_EA1_EB0 -> DistanceType.EE_EA1_EB1;
            case EE_EA1_EB1 -> DistanceType.EE_EA1_EB0;
            case EE_EA_EB0 -> DistanceType.EE_EA_EB1;
            case EE_EA_EB1 -> DistanceType.EE_EA_EB0;
            default -> t;
        };
    }

    private static DistanceType swapEdges(DistanceType t) {
        return switch (t) {
            case EE_EA0_EB1 -> DistanceType.EE_EA1_EB0;
            case EE_EA1_EB0 -> DistanceType.EE_EA0_EB1;
            case EE_EA_EB0 -> DistanceType.EE_EA0_EB;
            case EE_EA_EB1 -> DistanceType.EE_EA1_EB;
            case EE_EA0_EB -> DistanceType.EE_EA_EB0;
            case EE_EA1_EB -> DistanceType.EE_EA_EB1;
            default -> t;
        };
    }

    /** Sorts by key and drops repeats (the key encodes kind and nodes). */
    private void deduplicate() {
        Integer[] idx = new Integer[count];
        for (int i = 0; i < count; i++) {
            idx[i] = i;
        }
        Arrays.sort(idx, (a, b) -> Long.compare(keys[a], keys[b]));
        int[] k2 = new int[count];
        int[] n2 = new int[4 * count];
        double[] xi2 = new double[count];
        double[] eps2 = new double[count];
        DistanceType[] m2 = new DistanceType[count];
        long[] key2 = new long[count];
        int out = 0;
        for (int i = 0; i < count; i++) {
            int s = idx[i];
            if (out > 0 && key2[out - 1] == keys[s]) {
                continue;
            }
            k2[out] = kind[s];
            System.arraycopy(nodes, 4 * s, n2, 4 * out, 4);
            xi2[out] = xi[s];
            eps2[out] = epsX[s];
            m2[out] = mollified[s];
            key2[out] = keys[s];
            out++;
        }
        System.arraycopy(k2, 0, kind, 0, out);
        System.arraycopy(n2, 0, nodes, 0, 4 * out);
        System.arraycopy(xi2, 0, xi, 0, out);
        System.arraycopy(eps2, 0, epsX, 0, out);
        System.arraycopy(m2, 0, mollified, 0, out);
        System.arraycopy(key2, 0, keys, 0, out);
        count = out;
    }

    /** Node pairs coupled by the active contacts (for the sparsity pattern). */
    public void couplings(PairVisitor pair) {
        for (int c = 0; c < count; c++) {
            int k = NODES_OF_KIND[kind[c]];
            for (int i = 0; i < k; i++) {
                for (int j = i + 1; j < k; j++) {
                    pair.accept(nodes[4 * c + i], nodes[4 * c + j]);
                }
            }
        }
    }

    int nodeCount(int c) {
        return NODES_OF_KIND[kind[c]];
    }

    int node(int c, int i) {
        return nodes[4 * c + i];
    }

    /** Squared distance of contact c at x, with derivatives in its stencil when the arrays are given. */
    double distance2(int c, double[] x, double[] grad, double[] hess) {
        return distance2(c, x, grad, hess, scratch.pos);
    }

    /** As {@link #distance2(int, double[], double[], double[])}, the stencil's positions left in {@code buf}. */
    private double distance2(int c, double[] x, double[] grad, double[] hess, double[] buf) {
        int k = NODES_OF_KIND[kind[c]];
        for (int i = 0; i < k; i++) {
            int n = 3 * nodes[4 * c + i];
            buf[3 * i] = x[n];
            buf[3 * i + 1] = x[n + 1];
            buf[3 * i + 2] = x[n + 2];
        }
        switch (kind[c]) {
            case VV:
                return Distances.pointPoint(buf, grad, hess);
            case EV:
                return Distances.pointLine(buf, grad, hess);
            case FV:
                return Distances.pointPlane(buf, grad, hess);
            case EE:
                return mollified[c] != null ? Distances.evaluate(mollified[c], buf, grad, hess, 4) : Distances.lineLine(buf, grad, hess);
            default:
                double d = buf[2] - mesh.groundHeight;
                if (grad != null) {
                    grad[0] = 0;
                    grad[1] = 0;
                    grad[2] = 2 * d;
                }
                if (hess != null) {
                    Arrays.fill(hess, 0, 9, 0.0);
                    hess[8] = 2;
                }
                return d * d;
        }
    }

    /** Mollifier of contact c (its positions in buf), with derivatives; 1 unless mollified. */
    private double mollifier(int c, double[] buf, double[] grad, double[] hess) {
        if (kind[c] != EE || mollified[c] == null) {
            return 1;
        }
        return EdgeEdgeMollifier.evaluate(buf, epsX[c], grad, hess);
    }

    /** κ Σ m b(s): the barrier energy at x (the set built at x); +∞ if any pair touches. */
    public double energy(double[] x, double kappa) {
        return energy(x, kappa, 0, count, scratch);
    }

    /** The barrier energy of contacts [from, to). */
    public double energy(double[] x, double kappa, int from, int to, Scratch w) {
        double e = 0;
        for (int c = from; c < to; c++) {
            double s = distance2(c, x, null, null, w.pos) - xi[c] * xi[c];
            if (s <= 0) {
                return Double.POSITIVE_INFINITY;
            }
            e += mollifier(c, w.pos, null, null) * Barrier.value(s, activation(xi[c]));
        }
        return kappa * e;
    }

    /** Adds the barrier gradient to g (all nodes). */
    public void addGradient(double[] x, double kappa, double[] g) {
        addGradient(x, kappa, 0, count, g, scratch);
    }

    /** Adds the barrier gradient of contacts [from, to) to g. */
    public void addGradient(double[] x, double kappa, int from, int to, double[] g, Scratch w) {
        double[] gradD = w.gradD;
        double[] gradM = w.gradM;
        for (int c = from; c < to; c++) {
            int k = NODES_OF_KIND[kind[c]];
            double s = distance2(c, x, gradD, null, w.pos) - xi[c] * xi[c];
            double sh = activation(xi[c]);
            boolean molly = kind[c] == EE && mollified[c] != null;
            double m = mollifier(c, w.pos, gradM, null);
            double b1 = Barrier.slope(s, sh);
            double b = molly ? Barrier.value(s, sh) : 0;
            for (int i = 0; i < k; i++) {
                int n = 3 * nodes[4 * c + i];
                for (int d = 0; d < 3; d++) {
                    double gm = molly ? gradM[3 * i + d] : 0;
                    g[n + d] += kappa * (m * b1 * gradD[3 * i + d] + b * gm);
                }
            }
        }
    }

    /** Sends the (projected) barrier Hessian of each contact to the sink. */
    public void addHessian(double[] x, double kappa, HessianSink sink, boolean project) {
        addHessian(x, kappa, 0, count, sink, project, scratch);
    }

    /** Sends the (projected) barrier Hessians of contacts [from, to) to the sink. */
    public void addHessian(double[] x, double kappa, int from, int to, HessianSink sink, boolean project, Scratch w) {
        double[] gradD = w.gradD;
        double[] hessD = w.hessD;
        double[] gradM = w.gradM;
        double[] hessM = w.hessM;
        double[] local = w.local;
        int[] localNodes = w.localNodes;
        for (int c = from; c < to; c++) {
            int k = NODES_OF_KIND[kind[c]];
            int n = 3 * k;
            double s = distance2(c, x, gradD, hessD, w.pos) - xi[c] * xi[c];
            double sh = activation(xi[c]);
            double b = Barrier.value(s, sh);
            double b1 = Barrier.slope(s, sh);
            double b2 = Barrier.curvature(s, sh);
            boolean molly = kind[c] == EE && mollified[c] != null;
            double m = molly ? EdgeEdgeMollifier.evaluate(w.pos, epsX[c], gradM, hessM) : 1;
            for (int i = 0; i < n; i++) {
                for (int j = 0; j < n; j++) {
                    double h = m * (b2 * gradD[i] * gradD[j] + b1 * hessD[i * n + j]);
                    if (molly) {
                        h += b1 * (gradM[i] * gradD[j] + gradD[i] * gradM[j]) + b * hessM[i * n + j];
                    }
                    local[i * n + j] = kappa * h;
                }
            }
            if (project) {
                w.eigen.projectToPsd(local, n);
            }
            for (int i = 0; i < k; i++) {
                localNodes[i] = nodes[4 * c + i];
            }
            sink.add(localNodes, k, local);
        }
    }

    /** Smallest gap d − ξ over the active contacts at x, or d̂ if none is active. */
    public double minGap(double[] x) {
        double gap = dhat;
        for (int c = 0; c < count; c++) {
            gap = Math.min(gap, Math.sqrt(distance2(c, x, null, null)) - xi[c]);
        }
        return gap;
    }

    /** Smallest d² − ξ² over the active contacts (IPC's measure for the κ update), or ŝ of the largest offset. */
    public double minSquaredGap(double[] x) {
        double m = activation(mesh.maxOffset());
        for (int c = 0; c < count; c++) {
            m = Math.min(m, distance2(c, x, null, null) - xi[c] * xi[c]);
        }
        return m;
    }

    // ---- continuous collision detection ----------------------------------------------------------

    /**
     * The largest fraction α ≤ 1 of the update p such that the motion from x to x + α p keeps every
     * pair apart by more than its offset, by additive CCD with rescaling η (Codim-IPC uses 0.9).
     */
    public double largestSafeStep(double[] x, double[] p, double eta) {
        int n = x.length;
        double[] x1 = new double[n];
        for (int i = 0; i < n; i++) {
            x1[i] = x[i] + p[i];
        }
        candidates(x, x1, mesh.maxOffset());
        double alpha = 1;
        double[] a0 = new double[12];
        double[] a1 = new double[12];
        for (int k = 0; k < ptCount; k++) {
            int f = ptPairs[2 * k];
            int v = ptPairs[2 * k + 1];
            int t0 = mesh.faces[3 * f];
            int t1 = mesh.faces[3 * f + 1];
            int t2 = mesh.faces[3 * f + 2];
            gather(x, a0, v, t0, t1, t2);
            gather(x1, a1, v, t0, t1, t2);
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
            gather(x, a0, p0, p1, q0, q1);
            gather(x1, a1, p0, p1, q0, q1);
            double toi = AdditiveCcd.edgeEdge(a0, a1, mesh.offset(p0, q0), eta, alpha);
            alpha = Math.min(alpha, toi);
        }
        if (mesh.hasGround) {
            for (int v = 0; v < mesh.vertices.length; v++) {
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
