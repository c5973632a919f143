package handsim.cards.contact;

import handsim.cards.energy.HessianSink;
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
 * A merged contact keeps its multiplicity, the number of pairs that reduced to it, and its
 * barrier counts that often (as the IPC Toolkit's constraint weights): the sum stays the sum over
 * all vertex–face and edge–edge pairs, which is continuous where a pair's closest feature
 * changes; dropping the repeats would make E jump there, and the line search stall.
 * Nearly parallel edge pairs keep their edge–edge stencil with the mollifier.
 *
 * <p>The broad phase and the continuous collision detection over swept boxes are {@link
 * ContactCandidates}'.
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
    private final ContactCandidates candidates;
    private boolean gaussNewton;

    // active contacts (parallel arrays, sorted by key)
    int count;
    int[] kind = new int[256];
    int[] nodes = new int[4 * 256];
    double[] xi = new double[256];
    double[] epsX = new double[256];
    /** how many candidate pairs (vertex–face, edge–edge) reduce to each contact: its barrier counts that often */
    int[] multiplicity = new int[256];
    DistanceType[] mollified = new DistanceType[256];
    long[] keys = new long[256];

    // workspace
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
        this.candidates = new ContactCandidates(mesh, cellSize);
    }

    /**
     * Sets the memory budgets of the broad phase: (cell, id) entries per spatial hash and
     * candidate pairs per query; past them a build throws {@link BudgetExceeded}.
     */
    public void limit(long hashEntries, long candidatePairs) {
        candidates.limit(hashEntries, candidatePairs);
    }

    public int size() {
        return count;
    }

    /**
     * Whether {@link #addHessian} with {@code project} gives each contact's Gauss–Newton Hessian
     * κ w b''(s) ∇s ∇sᵀ, positive semi-definite by construction, instead of projecting the full
     * Hessian κ w (b''(s) ∇s ∇sᵀ + b'(s) ∇²s) by eigen-decomposition. The dropped term bends
     * the barrier's level sets: along the normal it is s/(2d²) of the kept one, about 2 % for
     * cards a few micrometres apart at their 0.25 mm offset, and across it the projection clamps
     * most of it to zero anyway. A mollified edge–edge contact's energy m b(s) gets the
     * Gauss–Newton Hessian of that product ({@link #gaussNewtonHessian}).
     */
    public void useGaussNewton(boolean on) {
        this.gaussNewton = on;
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

    // ---- narrow phase --------------------------------------------------------------------------

    /** Finds the barrier-active contacts at x. */
    public void build(double[] x) {
        candidates.find(x, null, mesh.maxOffset() + dhat);
        narrowPhase(x);
    }

    /**
     * Finds the barrier-active contacts at a point x + α p (0 ≤ α ≤ 1) of the motion last passed
     * to {@link #largestSafeStep}: its candidates, gathered over the swept boxes grown by the
     * activation distance, hold every pair that can be active anywhere along that motion, so
     * the line search needs no broad phase of its own.
     */
    public void buildAlongSweep(double[] x) {
        narrowPhase(x);
    }

    private void narrowPhase(double[] x) {
        int ptCount = candidates.ptCount;
        int[] ptPairs = candidates.ptPairs;
        int eeCount = candidates.eeCount;
        int[] eePairs = candidates.eePairs;
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
                if (mesh.fixedNode[p]) {
                    continue;
                }
                double offset = mesh.halfThickness[mesh.bodyOfNode[p]];
                double d = x[3 * p + 2] - mesh.groundHeight;
                if (d * d - offset * offset < activation(offset)) {
                    add(GROUND, offset, 0, null, p);
                }
            }
        }
        DuplicateContacts.merge(this);
    }

    static void gather(double[] x, double[] out, int... ns) {
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
            multiplicity = Arrays.copyOf(multiplicity, cap);
            keys = Arrays.copyOf(keys, cap);
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
                molly = molly == null ? null : molly.withEdgeAReversed();
            }
            if (c[2] > c[3]) {
                swap(c, 2, 3);
                molly = molly == null ? null : molly.withEdgeBReversed();
            }
            if (c[0] > c[2]) {
                swap(c, 0, 2);
                swap(c, 1, 3);
                molly = molly == null ? null : molly.withEdgesSwapped();
            }
        }
        kind[count] = k;
        for (int i = 0; i < 4; i++) {
            nodes[4 * count + i] = i < c.length ? c[i] : -1;
        }
        xi[count] = offset;
        epsX[count] = eps;
        multiplicity[count] = 1;
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
            e += multiplicity[c] * mollifier(c, w.pos, null, null) * Barrier.value(s, activation(xi[c]));
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
            double weight = kappa * multiplicity[c];
            for (int i = 0; i < k; i++) {
                int n = 3 * nodes[4 * c + i];
                for (int d = 0; d < 3; d++) {
                    double gm = molly ? gradM[3 * i + d] : 0;
                    g[n + d] += weight * (m * b1 * gradD[3 * i + d] + b * gm);
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
            for (int i = 0; i < k; i++) {
                localNodes[i] = nodes[4 * c + i];
            }
            if (project && gaussNewton) {
                gaussNewtonHessian(c, x, kappa, w);
                sink.add(localNodes, k, local);
                continue;
            }
            double s = distance2(c, x, gradD, hessD, w.pos) - xi[c] * xi[c];
            double sh = activation(xi[c]);
            double b = Barrier.value(s, sh);
            double b1 = Barrier.slope(s, sh);
            double b2 = Barrier.curvature(s, sh);
            boolean molly = kind[c] == EE && mollified[c] != null;
            double m = molly ? EdgeEdgeMollifier.evaluate(w.pos, epsX[c], gradM, hessM) : 1;
            double weight = kappa * multiplicity[c];
            for (int i = 0; i < n; i++) {
                for (int j = 0; j < n; j++) {
                    double h = m * (b2 * gradD[i] * gradD[j] + b1 * hessD[i * n + j]);
                    if (molly) {
                        h += b1 * (gradM[i] * gradD[j] + gradD[i] * gradM[j]) + b * hessM[i * n + j];
                    }
                    local[i * n + j] = weight * h;
                }
            }
            if (project) {
                w.eigen.projectToPsd(local, n);
            }
            sink.add(localNodes, k, local);
        }
    }

    /**
     * Contact c's Gauss–Newton Hessian into {@code w.local}: κ w b''(s) ∇s ∇sᵀ; for a mollified
     * edge–edge contact, whose energy is κ w φ(m, s) with φ = m b(s), Jᵀ [∇²φ]₊ J with J the rows
     * ∇m and ∇s and [∇²φ]₊ the positive part of φ's 2x2 Hessian [[0, b'], [b', m b'']] (one
     * eigenvalue of each sign): rank one, semi-definite, no eigen-decomposition of the stencil.
     */
    private void gaussNewtonHessian(int c, double[] x, double kappa, Scratch w) {
        int n = 3 * NODES_OF_KIND[kind[c]];
        double s = distance2(c, x, w.gradD, null, w.pos) - xi[c] * xi[c];
        double sh = activation(xi[c]);
        double weight = kappa * multiplicity[c];
        double[] dir = w.gradM;
        if (kind[c] == EE && mollified[c] != null) {
            double m = EdgeEdgeMollifier.evaluate(w.pos, epsX[c], dir, null);
            double b1 = Barrier.slope(s, sh);
            double b2m = m * Barrier.curvature(s, sh);
            double lambda = 0.5 * (b2m + Math.sqrt(b2m * b2m + 4 * b1 * b1));
            double norm = Math.hypot(b1, lambda);
            double um = norm > 0 ? b1 / norm : 0;
            double us = norm > 0 ? lambda / norm : 1;
            for (int i = 0; i < n; i++) {
                dir[i] = um * dir[i] + us * w.gradD[i];
            }
            weight *= lambda;
        } else {
            System.arraycopy(w.gradD, 0, dir, 0, n);
            weight *= Barrier.curvature(s, sh);
        }
        for (int i = 0; i < n; i++) {
            double di = weight * dir[i];
            for (int j = 0; j < n; j++) {
                w.local[i * n + j] = di * dir[j];
            }
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

    /**
     * The largest fraction α ≤ 1 of the update p such that the motion from x to x + α p keeps every
     * pair apart by more than its offset ({@link ContactCandidates#largestSafeStep}).
     */
    public double largestSafeStep(double[] x, double[] p, double eta) {
        // grown by the activation distance too: the same candidates serve buildAlongSweep
        return candidates.largestSafeStep(x, p, eta, mesh.maxOffset() + dhat);
    }
}
