package handsim.cards.linalg;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;

/**
 * Sparse LLᵀ of a symmetric positive definite matrix made of 3x3 node blocks: multifrontal over
 * supernodes (nodes of the elimination tree with nested structures, Liu 1992), each front a
 * dense column-major matrix factored by blocked loops that the JIT vectorises.
 *
 * <p>The symbolic part (elimination tree, column structures, supernodes, the fronts' index maps
 * and storage) is built once per pattern; {@link #factor} refills the values. The node ordering
 * must be a postorder of its elimination tree (so a supernode's nodes are consecutive), as
 * {@link SymbolicAnalysis#postorder} makes it. With {@code parallel} set, the two heaviest disjoint subtrees of
 * the supernode tree are factored on two threads and the rest on one; every front adds its
 * children's updates in the same fixed order either way, so the factor is the same bit for bit.
 *
 * <p>Input: the upper triangle in compressed columns over 3N dofs, node k's columns 3k..3k+2
 * holding the 3x3 blocks of its neighbours {@code lower[k]} (sorted, all below k) followed by its
 * own upper 3x3 triangle, as {@link SparseSpdSystem} lays them out.
 */
final class SupernodalCholesky {

    private final int nodes;
    private final int[] pointers;
    private final boolean parallel;

    // supernodes: first node, node count, front node list (own nodes, then the rows below)
    private final int supernodeCount;
    private final int[] firstNode;
    private final int[] size;
    private final int[][] frontNodes;
    /** for each supernode: the dof (in the node ordering) of each front row */
    private final int[][] rowDof;
    private final int[][] children;
    /** for each supernode: where its front receives the A entries (value index → front index pairs) */
    private final int[][] assembleFrom;
    private final int[][] assembleTo;
    /** for each supernode, per child: the front index of each of the child's update rows */
    private final int[][][] childMap;
    /** factor panels (front rows × own columns) and update matrices (rows below, square) */
    private final double[][] panel;
    private final double[][] update;
    /** supernodes in the order they are factored, as [first, end) ranges per phase */
    private final int[] order;
    private final int[] phaseEnds;
    private final double[][] fronts = new double[2][];
    /** the solve's scratch: one front's rows below its own columns */
    private final double[] gathered;

    /**
     * @param lower per node, its sorted neighbours below it (the pattern of its upper columns)
     * @param pointers the compressed-column pointers of the 3N dofs (see class comment)
     */
    SupernodalCholesky(int[][] lower, int[] pointers, boolean parallel) {
        this.nodes = lower.length;
        this.pointers = pointers;
        this.parallel = parallel;
        int n = nodes;
        // upper lists: for node j, the nodes k > j coupled to it, with j's slot in lower[k]
        int[] upperCount = new int[n];
        for (int[] l : lower) {
            for (int j : l) {
                upperCount[j]++;
            }
        }
        int[][] upperNode = new int[n][];
        int[][] upperSlot = new int[n][];
        for (int j = 0; j < n; j++) {
            upperNode[j] = new int[upperCount[j]];
            upperSlot[j] = new int[upperCount[j]];
        }
        Arrays.fill(upperCount, 0);
        for (int k = 0; k < n; k++) {
            for (int s = 0; s < lower[k].length; s++) {
                int j = lower[k][s];
                upperNode[j][upperCount[j]] = k;
                upperSlot[j][upperCount[j]++] = s;
            }
        }
        int[] parent = SymbolicAnalysis.parents(lower);
        for (int j = 0; j < n; j++) {
            if (parent[j] >= 0 && parent[j] <= j) {
                throw new IllegalArgumentException("the node ordering is not a postorder of its elimination tree");
            }
        }
        // column structures of L (nodes below the diagonal), children before parents
        int[][] structure = new int[n][];
        int[] childCount = new int[n];
        List<List<Integer>> nodeChildren = new ArrayList<>();
        for (int j = 0; j < n; j++) {
            nodeChildren.add(new ArrayList<>());
        }
        for (int j = 0; j < n; j++) {
            if (parent[j] >= 0) {
                childCount[parent[j]]++;
                nodeChildren.get(parent[j]).add(j);
            }
        }
        int[] mark = new int[n];
        Arrays.fill(mark, -1);
        int[] buffer = new int[n];
        for (int j = 0; j < n; j++) {
            int count = 0;
            for (int k : upperNode[j]) {
                if (mark[k] != j) {
                    mark[k] = j;
                    buffer[count++] = k;
                }
            }
            for (int c : nodeChildren.get(j)) {
                for (int k : structure[c]) {
                    if (k != j && mark[k] != j) {
                        mark[k] = j;
                        buffer[count++] = k;
                    }
                }
            }
            structure[j] = Arrays.copyOf(buffer, count);
            Arrays.sort(structure[j]);
        }
        List<Integer> firsts = SymbolicAnalysis.amalgamatedSupernodes(parent, childCount, structure);
        int[] supernodeOf = new int[n];
        for (int t = 0; t < firsts.size(); t++) {
            int end = t + 1 < firsts.size() ? firsts.get(t + 1) : n;
            Arrays.fill(supernodeOf, firsts.get(t), end, t);
        }
        supernodeCount = firsts.size();
        firstNode = new int[supernodeCount];
        size = new int[supernodeCount];
        frontNodes = new int[supernodeCount][];
        rowDof = new int[supernodeCount][];
        for (int s = 0; s < supernodeCount; s++) {
            firstNode[s] = firsts.get(s);
            int end = s + 1 < supernodeCount ? firsts.get(s + 1) : n;
            size[s] = end - firstNode[s];
            int[] below = structure[end - 1];
            int[] front = new int[size[s] + below.length];
            for (int i = 0; i < size[s]; i++) {
                front[i] = firstNode[s] + i;
            }
            System.arraycopy(below, 0, front, size[s], below.length);
            frontNodes[s] = front;
            rowDof[s] = new int[3 * front.length];
            for (int i = 0; i < 3 * front.length; i++) {
                rowDof[s][i] = 3 * front[i / 3] + i % 3;
            }
        }
        int[] superParent = new int[supernodeCount];
        List<List<Integer>> kids = new ArrayList<>();
        for (int s = 0; s < supernodeCount; s++) {
            kids.add(new ArrayList<>());
        }
        for (int s = 0; s < supernodeCount; s++) {
            int last = firstNode[s] + size[s] - 1;
            superParent[s] = parent[last] < 0 ? -1 : supernodeOf[parent[last]];
            if (superParent[s] >= 0) {
                kids.get(superParent[s]).add(s);
            }
        }
        children = new int[supernodeCount][];
        for (int s = 0; s < supernodeCount; s++) {
            children[s] = kids.get(s).stream().mapToInt(Integer::intValue).toArray();
        }
        // index maps of each front: A's entries, and the children's update rows
        int[] local = new int[n];
        assembleFrom = new int[supernodeCount][];
        assembleTo = new int[supernodeCount][];
        childMap = new int[supernodeCount][][];
        panel = new double[supernodeCount][];
        update = new double[supernodeCount][];
        int maxFront = 0;
        for (int s = 0; s < supernodeCount; s++) {
            int[] front = frontNodes[s];
            int m = 3 * front.length;
            int k = 3 * size[s];
            maxFront = Math.max(maxFront, m);
            for (int i = 0; i < front.length; i++) {
                local[front[i]] = i;
            }
            int entries = 0;
            for (int a = 0; a < size[s]; a++) {
                entries += 6 + 9 * upperNode[firstNode[s] + a].length;
            }
            int[] from = new int[entries];
            int[] to = new int[entries];
            int e = 0;
            for (int a = 0; a < size[s]; a++) {
                int node = firstNode[s] + a;
                int diagonalAt = lower[node].length * 3;
                for (int c = 0; c < 3; c++) {
                    for (int r = 0; r <= c; r++) {
                        // A(3node + r, 3node + c), stored upper; kept in the lower triangle at (c, r)
                        from[e] = pointers[3 * node + c] + diagonalAt + r;
                        to[e++] = (3 * a + c) + (3 * a + r) * m;
                    }
                }
                for (int t = 0; t < upperNode[node].length; t++) {
                    int i = upperNode[node][t];
                    int slot = upperSlot[node][t];
                    int li = local[i];
                    for (int c = 0; c < 3; c++) {
                        for (int r = 0; r < 3; r++) {
                            // A(3node + r, 3i + c) in column 3i + c; lower triangle (3i + c, 3node + r)
                            from[e] = pointers[3 * i + c] + 3 * slot + r;
                            to[e++] = (3 * li + c) + (3 * a + r) * m;
                        }
                    }
                }
            }
            assembleFrom[s] = from;
            assembleTo[s] = to;
            childMap[s] = new int[children[s].length][];
            for (int ci = 0; ci < children[s].length; ci++) {
                int[] cf = frontNodes[children[s][ci]];
                int cs = size[children[s][ci]];
                int[] map = new int[3 * (cf.length - cs)];
                for (int p = 0; p < cf.length - cs; p++) {
                    for (int d = 0; d < 3; d++) {
                        map[3 * p + d] = 3 * local[cf[cs + p]] + d;
                    }
                }
                childMap[s][ci] = map;
            }
            panel[s] = new double[m * k];
            update[s] = new double[(m - k) * (m - k)];
        }
        gathered = new double[maxFront];
        fronts[0] = new double[maxFront * maxFront];
        fronts[1] = new double[maxFront * maxFront];
        // factoring order: two disjoint subtrees (balanced by work) then the rest, all in postorder
        long[] work = new long[supernodeCount];
        for (int s = 0; s < supernodeCount; s++) {
            long m = 3L * frontNodes[s].length;
            work[s] += m * m * 3L * size[s];
            if (superParent[s] >= 0) {
                work[superParent[s]] += work[s];
            }
        }
        order = new int[supernodeCount];
        phaseEnds = new int[3];
        splitForTwoThreads(superParent, work);
    }

    /** Picks two disjoint subtrees to factor side by side: the heaviest, then the heaviest not inside it. */
    private void splitForTwoThreads(int[] superParent, long[] work) {
        int[] subtreeStart = new int[supernodeCount];
        for (int s = 0; s < supernodeCount; s++) {
            subtreeStart[s] = s;
        }
        for (int s = 0; s < supernodeCount; s++) {
            if (superParent[s] >= 0) {
                subtreeStart[superParent[s]] = Math.min(subtreeStart[superParent[s]], subtreeStart[s]);
            }
        }
        // candidates: subtrees whose root's parent's subtree is too heavy to give one thread
        long total = 0;
        for (int s = 0; s < supernodeCount; s++) {
            if (superParent[s] < 0) {
                total += work[s];
            }
        }
        int first = -1;
        int second = -1;
        for (int s = 0; s < supernodeCount; s++) {
            boolean small = work[s] * 2 <= total;
            boolean parentBig = superParent[s] < 0 || work[superParent[s]] * 2 > total;
            if (small && parentBig) {
                if (first < 0 || work[s] > work[first]) {
                    second = first;
                    first = s;
                } else if (second < 0 || work[s] > work[second]) {
                    second = s;
                }
            }
        }
        boolean[] placed = new boolean[supernodeCount];
        int at = 0;
        for (int phase = 0; phase < 2; phase++) {
            int root = phase == 0 ? first : second;
            if (root >= 0) {
                for (int s = subtreeStart[root]; s <= root; s++) {
                    order[at++] = s;
                    placed[s] = true;
                }
            }
            phaseEnds[phase] = at;
        }
        for (int s = 0; s < supernodeCount; s++) {
            if (!placed[s]) {
                order[at++] = s;
            }
        }
        phaseEnds[2] = at;
    }

    /** Factors the matrix whose values are given (the layout of the constructor's pointers); false if not positive definite. */
    boolean factor(double[] values) {
        if (parallel && phaseEnds[0] > 0 && phaseEnds[1] > phaseEnds[0]) {
            ForkJoinTask<Boolean> side = ForkJoinPool.commonPool().submit(() -> factorRange(values, phaseEnds[0], phaseEnds[1], fronts[1]));
            boolean ok = factorRange(values, 0, phaseEnds[0], fronts[0]);
            ok &= side.join();
            return ok && factorRange(values, phaseEnds[1], phaseEnds[2], fronts[0]);
        }
        return factorRange(values, 0, phaseEnds[2], fronts[0]);
    }

    private boolean factorRange(double[] values, int from, int to, double[] front) {
        for (int t = from; t < to; t++) {
            if (!factorSupernode(order[t], values, front)) {
                return false;
            }
        }
        return true;
    }

    /** Assembles supernode s's front, eliminates its own columns, keeps its panel and update. */
    private boolean factorSupernode(int s, double[] values, double[] f) {
        int m = 3 * frontNodes[s].length;
        int k = 3 * size[s];
        for (int q = 0; q < m; q++) {
            Arrays.fill(f, q + q * m, (q + 1) * m, 0.0);
        }
        int[] from = assembleFrom[s];
        int[] to = assembleTo[s];
        for (int e = 0; e < from.length; e++) {
            f[to[e]] += values[from[e]];
        }
        for (int ci = 0; ci < children[s].length; ci++) {
            double[] u = update[children[s][ci]];
            int[] map = childMap[s][ci];
            int mc = map.length;
            for (int q = 0; q < mc; q++) {
                int col = map[q] * m;
                int uq = q * mc;
                for (int p = q; p < mc; p++) {
                    f[map[p] + col] += u[p + uq];
                }
            }
        }
        // own columns, left-looking within the panel
        for (int j = 0; j < k; j++) {
            int cj = j * m;
            for (int p = 0; p < j; p++) {
                subtractScaled(f, cj, p * m, j, m, f[j + p * m]);
            }
            double d = f[j + cj];
            if (!(d > 1e-300)) {
                return false;
            }
            double inv = 1 / Math.sqrt(d);
            for (int i = j; i < m; i++) {
                f[i + cj] *= inv;
            }
        }
        // the update of the rows below: F22 − L21 L21ᵀ
        for (int q = k; q < m; q++) {
            for (int p = 0; p < k; p++) {
                subtractScaled(f, q * m, p * m, q, m, f[q + p * m]);
            }
        }
        System.arraycopy(f, 0, panel[s], 0, m * k);
        int mu = m - k;
        double[] u = update[s];
        for (int q = 0; q < mu; q++) {
            System.arraycopy(f, (k + q) + (k + q) * m, u, q + q * mu, mu - q);
        }
        return true;
    }

    /** f[to + i] −= f[from + i] · scale for rows i in [first, end): one column update of a front. */
    private static void subtractScaled(double[] f, int to, int from, int first, int end, double scale) {
        for (int i = first; i < end; i++) {
            f[to + i] -= f[from + i] * scale;
        }
    }

    /** Solves L Lᵀ x = b in place (b in the node ordering's dofs). */
    void solve(double[] b) {
        double[] t = gathered;
        for (int s = 0; s < supernodeCount; s++) {
            int[] dof = rowDof[s];
            int m = dof.length;
            int k = 3 * size[s];
            double[] l = panel[s];
            int base = 3 * firstNode[s];
            for (int i = k; i < m; i++) {
                t[i] = 0;
            }
            for (int j = 0; j < k; j++) {
                int cj = j * m;
                double y = b[base + j] / l[j + cj];
                b[base + j] = y;
                for (int i = j + 1; i < k; i++) {
                    b[base + i] -= l[i + cj] * y;
                }
                for (int i = k; i < m; i++) {
                    t[i] += l[i + cj] * y;
                }
            }
            for (int i = k; i < m; i++) {
                b[dof[i]] -= t[i];
            }
        }
        for (int s = supernodeCount - 1; s >= 0; s--) {
            int[] dof = rowDof[s];
            int m = dof.length;
            int k = 3 * size[s];
            double[] l = panel[s];
            int base = 3 * firstNode[s];
            for (int i = k; i < m; i++) {
                t[i] = b[dof[i]];
            }
            for (int j = k - 1; j >= 0; j--) {
                int cj = j * m;
                double y = b[base + j];
                for (int i = j + 1; i < k; i++) {
                    y -= l[i + cj] * b[base + i];
                }
                for (int i = k; i < m; i++) {
                    y -= l[i + cj] * t[i];
                }
                b[base + j] = y / l[j + cj];
            }
        }
    }

    int supernodes() {
        return supernodeCount;
    }

    /** Stored entries of L (the panels). */
    long factorEntries() {
        long e = 0;
        for (double[] p : panel) {
            e += p.length;
        }
        return e;
    }
}
