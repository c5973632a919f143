package handsim.cards.linalg;

import edu.emory.mathcs.csparsej.tdouble.Dcs_amd;
import edu.emory.mathcs.csparsej.tdouble.Dcs_common.Dcs;
import java.util.Arrays;
import org.ojalgo.matrix.decomposition.SparseQDLDL;
import org.ojalgo.matrix.decomposition.SparseQDLDL.EliminationTree;
import org.ojalgo.matrix.store.R064CSC;

/**
 * The Newton system H Δx = −g of the card simulator: a symmetric positive definite matrix with
 * 3x3 blocks between the nodes that share an element or a contact, factored by ojAlgo's sparse
 * LDLᵀ ({@link SparseQDLDL}) after an approximate-minimum-degree ordering of the node graph
 * (CSparseJ's {@code cs_amd}).
 *
 * <p>The pattern (ordering, elimination tree, compressed-column layout) is rebuilt only when the
 * set of coupled node pairs changes; while it holds, each Newton iteration only refills the values
 * and refactors numerically. Node indices here are system indices (free nodes only).
 */
public final class SparseSpdSystem {

    /** The numeric factorisation: handsim's supernodal LLᵀ, or ojAlgo's QDLDL (both after the same ordering). */
    public enum Factorisation { SUPERNODAL, QDLDL }

    private final Factorisation factorisation;
    private final boolean parallel;
    private SupernodalCholesky supernodal;
    private final int nodes;
    private final int dofs;
    private long[] pairs = new long[0];
    /** permuted index of each node, and the node at each permuted index */
    private final int[] perm;
    private final int[] inverse;
    /** per permuted node: sorted permuted indices of its neighbours below it */
    private int[][] lower;
    /** per permuted node: index of its first value in the CSC arrays */
    private int[] base;
    private int[] pointers;
    private int[] indices;
    private double[] values;
    private R064CSC matrix;
    private EliminationTree tree;
    /** system dof of each permuted dof */
    private final int[] systemDof;
    private final SparseQDLDL ldl = new SparseQDLDL();
    private int patternBuilds;

    // the last numeric factorisation: its node permutation and diagonal scaling (ldl holds L and D)
    private boolean factored;
    private final int[] factorPerm;
    private final double[] factorScaling;
    private boolean refreshFactor;
    private final double[] work;
    private int factorisations;
    /** CG on H preconditioned by the kept factorisation */
    private final ConjugateGradients cg;
    private long cgIterations;
    private int shiftedFactorisations;

    public SparseSpdSystem(int nodes) {
        this(nodes, Factorisation.SUPERNODAL, false);
    }

    /** @param parallel factor on two threads where the elimination tree allows (bit-identical either way) */
    public SparseSpdSystem(int nodes, Factorisation factorisation, boolean parallel) {
        this.factorisation = factorisation;
        this.parallel = parallel;
        this.nodes = nodes;
        this.dofs = 3 * nodes;
        this.perm = new int[nodes];
        this.inverse = new int[nodes];
        this.systemDof = new int[dofs];
        this.factorPerm = new int[nodes];
        this.factorScaling = new double[dofs];
        this.work = new double[dofs];
        this.cg = new ConjugateGradients(dofs, this::multiply, (r, z) -> applyFactor(r, z, work));
    }

    /** The key of an unordered node pair. */
    public static long pairKey(int a, int b) {
        int lo = Math.min(a, b);
        int hi = Math.max(a, b);
        return ((long) lo << 32) | hi;
    }

    /**
     * Sets the coupled node pairs (sorted, distinct keys of {@link #pairKey}, a ≠ b); rebuilds the
     * ordering and symbolic structure only if they differ from the current ones. Returns whether
     * it rebuilt.
     */
    public boolean setPattern(long[] sortedPairs) {
        if (lower != null && Arrays.equals(sortedPairs, pairs)) {
            return false;
        }
        pairs = sortedPairs.clone();
        refreshFactor = true;
        order();
        layout();
        patternBuilds++;
        return true;
    }

    /** How many times the symbolic structure was built. */
    public int patternBuilds() {
        return patternBuilds;
    }

    private void order() {
        // symmetric node graph in CSC (both triangles, no diagonal) for cs_amd
        int[] degree = new int[nodes];
        for (long key : pairs) {
            degree[(int) (key >>> 32)]++;
            degree[(int) key]++;
        }
        int[] p = new int[nodes + 1];
        for (int i = 0; i < nodes; i++) {
            p[i + 1] = p[i] + degree[i];
        }
        int[] fill = Arrays.copyOf(p, nodes);
        int[] idx = new int[p[nodes]];
        for (long key : pairs) {
            int a = (int) (key >>> 32);
            int b = (int) key;
            idx[fill[a]++] = b;
            idx[fill[b]++] = a;
        }
        Dcs graph = new Dcs();
        graph.m = nodes;
        graph.n = nodes;
        graph.p = p;
        graph.i = idx;
        graph.x = null;
        graph.nz = -1;
        graph.nzmax = idx.length;
        int[] amd = nodes > 1 ? Dcs_amd.cs_amd(1, graph) : new int[] {0};
        // a postorder of AMD's elimination tree: the same fill, each subtree's nodes consecutive
        int[][] neighbours = new int[nodes][];
        for (int i = 0; i < nodes; i++) {
            neighbours[i] = Arrays.copyOfRange(idx, p[i], p[i + 1]);
        }
        amd = SymbolicAnalysis.postorder(neighbours, amd);
        for (int k = 0; k < nodes; k++) {
            inverse[k] = amd[k];
            perm[amd[k]] = k;
        }
    }

    private void layout() {
        int[] count = new int[nodes];
        for (long key : pairs) {
            int pa = perm[(int) (key >>> 32)];
            int pb = perm[(int) key];
            count[Math.max(pa, pb)]++;
        }
        lower = new int[nodes][];
        for (int k = 0; k < nodes; k++) {
            lower[k] = new int[count[k]];
        }
        int[] fill = new int[nodes];
        for (long key : pairs) {
            int pa = perm[(int) (key >>> 32)];
            int pb = perm[(int) key];
            int hi = Math.max(pa, pb);
            lower[hi][fill[hi]++] = Math.min(pa, pb);
        }
        base = new int[nodes + 1];
        pointers = new int[dofs + 1];
        for (int k = 0; k < nodes; k++) {
            Arrays.sort(lower[k]);
            int m = lower[k].length;
            base[k + 1] = base[k] + 9 * m + 6;
            for (int c = 0; c < 3; c++) {
                pointers[3 * k + c] = base[k] + c * 3 * m + c * (c + 1) / 2;
            }
        }
        pointers[dofs] = base[nodes];
        indices = new int[base[nodes]];
        for (int k = 0; k < nodes; k++) {
            int m = lower[k].length;
            for (int c = 0; c < 3; c++) {
                int at = pointers[3 * k + c];
                for (int s = 0; s < m; s++) {
                    for (int r = 0; r < 3; r++) {
                        indices[at++] = 3 * lower[k][s] + r;
                    }
                }
                for (int r = 0; r <= c; r++) {
                    indices[at++] = 3 * k + r;
                }
            }
        }
        values = new double[base[nodes]];
        for (int k = 0; k < nodes; k++) {
            for (int c = 0; c < 3; c++) {
                systemDof[3 * k + c] = 3 * inverse[k] + c;
            }
        }
        if (factorisation == Factorisation.SUPERNODAL) {
            supernodal = new SupernodalCholesky(lower, pointers, parallel);
        } else {
            matrix = new R064CSC(dofs, dofs, values, indices, pointers);
            tree = ldl.computeEliminationTree(matrix);
        }
    }

    /** Zeroes the values, keeping the pattern. */
    public void clear() {
        Arrays.fill(values, 0.0);
    }

    /**
     * Adds the 3x3 block {@code h[offset + 3r*stride + c]} (row r of node a, column c of node b)
     * and, for a ≠ b, implicitly its transpose at (b, a). The pair must be in the pattern.
     */
    public void addBlock(int a, int b, double[] h, int offset, int stride) {
        addBlock(a, b, h, offset, stride, 1.0);
    }

    /** {@link #addBlock(int, int, double[], int, int)} with the block times {@code scale}. */
    public void addBlock(int a, int b, double[] h, int offset, int stride, double scale) {
        addBlock(values, a, b, h, offset, stride, scale);
    }

    private void addBlock(double[] values, int a, int b, double[] h, int offset, int stride, double scale) {
        int pa = perm[a];
        int pb = perm[b];
        if (pa == pb) {
            int m = lower[pa].length;
            for (int c = 0; c < 3; c++) {
                int at = pointers[3 * pa + c] + 3 * m;
                for (int r = 0; r <= c; r++) {
                    values[at + r] += scale * h[offset + r * stride + c];
                }
            }
            return;
        }
        boolean transpose = pa > pb;
        int col = transpose ? pa : pb;
        int row = transpose ? pb : pa;
        int slot = Arrays.binarySearch(lower[col], row);
        if (slot < 0) {
            throw new IllegalStateException("node pair (" + a + ", " + b + ") is not in the pattern");
        }
        for (int c = 0; c < 3; c++) {
            int at = pointers[3 * col + c] + 3 * slot;
            for (int r = 0; r < 3; r++) {
                // entry (row node, component r; column node, component c)
                values[at + r] += scale * (transpose ? h[offset + c * stride + r] : h[offset + r * stride + c]);
            }
        }
    }

    /** Adds {@code d} to the three diagonal entries of node a. */
    public void addDiagonal(int a, double d) {
        addDiagonal(values, a, d);
    }

    private void addDiagonal(double[] values, int a, double d) {
        int pa = perm[a];
        int m = lower[pa].length;
        for (int c = 0; c < 3; c++) {
            values[pointers[3 * pa + c] + 3 * m + c] += d;
        }
    }

    /**
     * Factors the current values (which it scales in place); false if the matrix is not positive
     * definite. The matrix is first scaled symmetrically to a unit diagonal, D^{-1/2} H D^{-1/2}:
     * contact barriers make some diagonal entries many orders of magnitude above the masses, and
     * LDLᵀ's pivot test is relative to the largest pivot.
     */
    public boolean factor() {
        factored = false;
        if (scaling == null || scaling.length != dofs) {
            scaling = new double[dofs];
        }
        for (int j = 0; j < dofs; j++) {
            double d = values[pointers[j + 1] - 1];
            if (!(d > 0)) {
                return false;
            }
            scaling[j] = 1 / Math.sqrt(d);
        }
        for (int j = 0; j < dofs; j++) {
            double sj = scaling[j];
            for (int at = pointers[j]; at < pointers[j + 1]; at++) {
                values[at] *= scaling[indices[at]] * sj;
            }
        }
        return keepFactor(numericFactor());
    }

    private boolean numericFactor() {
        return factorisation == Factorisation.SUPERNODAL ? supernodal.factor(values) : ldl.factor(matrix, tree) && ldl.isSolvable();
    }

    private double[] scaling;

    /** Records a successful factorisation's permutation and scaling, for solves and as a preconditioner. */
    private boolean keepFactor(boolean ok) {
        factored = ok;
        if (ok) {
            factorisations++;
            System.arraycopy(perm, 0, factorPerm, 0, nodes);
            System.arraycopy(scaling, 0, factorScaling, 0, dofs);
        }
        return ok;
    }

    /**
     * After a failed {@link #factor()}: adds {@code delta} to the (unit, scaled) diagonal and
     * factors again. Barrier blocks can make the scaled matrix singular to working precision in
     * directions off the axes; a relative shift of 1e-10 or so restores a usable pivot without
     * changing the Newton direction noticeably.
     */
    public boolean refactorWithShift(double delta) {
        for (int j = 0; j < dofs; j++) {
            values[pointers[j + 1] - 1] += delta;
        }
        shiftedFactorisations++;
        return keepFactor(numericFactor());
    }

    /** Solves H x = b for the last factorisation; {@code b} (system order) is overwritten by x. */
    public void solve(double[] b, double[] work) {
        applyFactor(b, b, work);
    }

    /** out = (last factorisation)⁻¹ b, both in system order (they may be the same array). */
    private void applyFactor(double[] b, double[] out, double[] work) {
        for (int i = 0; i < nodes; i++) {
            int pi = factorPerm[i];
            for (int c = 0; c < 3; c++) {
                work[3 * pi + c] = b[3 * i + c] * factorScaling[3 * pi + c];
            }
        }
        if (factorisation == Factorisation.SUPERNODAL) {
            supernodal.solve(work);
        } else {
            ldl.ftran(work);
        }
        for (int i = 0; i < nodes; i++) {
            int pi = factorPerm[i];
            for (int c = 0; c < 3; c++) {
                out[3 * i + c] = work[3 * pi + c] * factorScaling[3 * pi + c];
            }
        }
    }

    /**
     * Solves H x = b for the values assembled since the last {@link #clear()} or {@link #sum};
     * {@code b} (system order) is overwritten by x. With a factorisation at hand it first tries
     * conjugate gradients on H preconditioned by that factorisation (of an earlier H, perhaps of
     * another pattern): when the preconditioned residual falls below {@code cgTolerance} times its
     * start within {@code cgMaxIterations}, that is the solution. Otherwise, or with
     * {@code cgMaxIterations} 0, H is factored afresh (with a growing diagonal shift if its scaled
     * pivots vanish) and solved directly; a CG solve that needed more than half the allowed
     * iterations makes the next call factor afresh. Returns false if H cannot be factored.
     */
    public boolean solve(double[] b, double cgTolerance, int cgMaxIterations) {
        if (factored && !refreshFactor && cgMaxIterations > 0) {
            int used = cg.solve(b, cgTolerance, cgMaxIterations);
            if (used > 0) {
                cgIterations += used;
                refreshFactor = used > cgMaxIterations / 2;
                System.arraycopy(cg.solution(), 0, b, 0, dofs);
                return true;
            }
            cgIterations += cgMaxIterations;
        }
        refreshFactor = false;
        boolean ok = factor();
        for (double shift = 1e-10; !ok && shift < 1; shift *= 100) {
            ok = refactorWithShift(shift);
        }
        if (ok) {
            solve(b, work);
        }
        return ok;
    }

    /** y = H x for the assembled (unscaled) values, in system order. */
    private void multiply(double[] x, double[] y) {
        Arrays.fill(y, 0);
        for (int j = 0; j < dofs; j++) {
            int sj = systemDof[j];
            double xj = x[sj];
            double yj = 0;
            int last = pointers[j + 1] - 1;
            for (int at = pointers[j]; at < last; at++) {
                int si = systemDof[indices[at]];
                double v = values[at];
                y[si] += v * xj;
                yj += v * x[si];
            }
            y[sj] += yj + values[last] * xj;
        }
    }

    /** Drops the kept factorisation: the next {@link #solve(double[], double, int)} factors afresh. */
    public void forgetFactorisation() {
        refreshFactor = true;
    }

    /** Numeric factorisations so far (shifted ones included). */
    public int factorisations() {
        return factorisations;
    }

    /** Conjugate-gradient iterations so far (a failed CG solve counts its limit). */
    public long cgIterations() {
        return cgIterations;
    }

    /** Factorisations that needed a diagonal shift. */
    public int shiftedFactorisations() {
        return shiftedFactorisations;
    }

    /**
     * A private buffer with the system's pattern that one assembly thread fills; {@link
     * #sum(Accumulator...)} adds the buffers in a fixed order, so the result does not depend on
     * how the threads were scheduled.
     */
    public final class Accumulator {
        private double[] buffer = new double[0];

        /** Zeroes the buffer (resized to the current pattern). */
        public void clear() {
            if (buffer.length != values.length) {
                buffer = new double[values.length];
            } else {
                Arrays.fill(buffer, 0.0);
            }
        }

        public void addBlock(int a, int b, double[] h, int offset, int stride, double scale) {
            SparseSpdSystem.this.addBlock(buffer, a, b, h, offset, stride, scale);
        }

        public void addDiagonal(int a, double d) {
            SparseSpdSystem.this.addDiagonal(buffer, a, d);
        }
    }

    public Accumulator accumulator() {
        return new Accumulator();
    }

    /** Sets the values to the sum of the accumulators, added in the order given. */
    public void sum(Accumulator... parts) {
        System.arraycopy(parts[0].buffer, 0, values, 0, values.length);
        for (int k = 1; k < parts.length; k++) {
            double[] b = parts[k].buffer;
            for (int i = 0; i < values.length; i++) {
                values[i] += b[i];
            }
        }
    }

    /** Number of stored (upper-triangle) entries. */
    public int nonzeros() {
        return values.length;
    }

    public int dofs() {
        return dofs;
    }
}
