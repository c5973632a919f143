package handsim.cards.linalg;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The symbolic analysis of a sparse symmetric pattern of node blocks, before any number is
 * factored: its elimination tree (Liu 1990), a postorder of it that keeps each subtree's nodes
 * consecutive with the same fill, and the supernodes {@link SupernodalCholesky} factors as
 * dense fronts.
 */
final class SymbolicAnalysis {

    private SymbolicAnalysis() {
    }

    /** The elimination tree of a pattern given by each node's neighbours below it (Liu's algorithm). */
    static int[] parents(int[][] lower) {
        int n = lower.length;
        int[] parent = new int[n];
        int[] ancestor = new int[n];
        Arrays.fill(parent, -1);
        Arrays.fill(ancestor, -1);
        for (int k = 0; k < n; k++) {
            for (int i : lower[k]) {
                int r = i;
                while (ancestor[r] >= 0 && ancestor[r] != k) {
                    int next = ancestor[r];
                    ancestor[r] = k;
                    r = next;
                }
                if (ancestor[r] < 0) {
                    ancestor[r] = k;
                    parent[r] = k;
                }
            }
        }
        return parent;
    }

    /**
     * A postorder of the elimination tree of a symmetric node graph under an ordering:
     * {@code neighbours[i]} lists node i's neighbours, {@code order[k]} is the k-th node (entries
     * past the node count are ignored). Returns
     * the nodes in the order that eliminates them with the same fill, each subtree consecutive.
     */
    static int[] postorder(int[][] neighbours, int[] order) {
        int n = neighbours.length;
        int[] position = new int[n];
        for (int k = 0; k < n; k++) {
            position[order[k]] = k;
        }
        int[][] lower = new int[n][];
        int[] buffer = new int[n];
        for (int k = 0; k < n; k++) {
            int count = 0;
            for (int j : neighbours[order[k]]) {
                if (position[j] < k) {
                    buffer[count++] = position[j];
                }
            }
            lower[k] = Arrays.copyOf(buffer, count);
        }
        int[] parent = parents(lower);
        // children lists in increasing order, then an iterative depth-first postorder
        int[] head = new int[n];
        int[] next = new int[n];
        Arrays.fill(head, -1);
        for (int j = n - 1; j >= 0; j--) {
            if (parent[j] >= 0) {
                next[j] = head[parent[j]];
                head[parent[j]] = j;
            }
        }
        int[] out = new int[n];
        int[] stack = new int[n];
        int at = 0;
        for (int root = 0; root < n; root++) {
            if (parent[root] >= 0) {
                continue;
            }
            int top = 0;
            stack[0] = root;
            while (top >= 0) {
                int j = stack[top];
                int child = head[j];
                if (child < 0) {
                    top--;
                    out[at++] = order[j];
                } else {
                    head[j] = next[child];
                    stack[++top] = child;
                }
            }
        }
        return out;
    }

    /**
     * The first node of each supernode. Fundamental supernodes first (node j joins j − 1's when
     * j − 1 is its only child and their structures nest), then relaxed amalgamation as in CHOLMOD
     * (Davis 2006): a supernode merges into its parent when it is the parent's last child (so
     * their nodes are consecutive) and the merged one has at most 4 nodes or stores under 5 %
     * explicit zeros. Looser rules (CHOLMOD's 80 % up to 16 nodes) made larger fronts but more
     * flops and no faster factorisation on the thesis fingertips.
     */
    static List<Integer> amalgamatedSupernodes(int[] parent, int[] childCount, int[][] structure) {
        int n = parent.length;
        List<Integer> fundamental = new ArrayList<>();
        for (int j = 0; j < n; j++) {
            boolean joins = j > 0 && parent[j - 1] == j && childCount[j] == 1 && structure[j - 1].length == structure[j].length + 1;
            if (!joins) {
                fundamental.add(j);
            }
        }
        // a stack of merged supernodes: first node, node count, rows below, zero blocks stored
        int f = fundamental.size();
        int[] first = new int[f];
        int[] count = new int[f];
        int[] below = new int[f];
        long[] zeros = new long[f];
        int top = -1;
        for (int t = 0; t < f; t++) {
            int start = fundamental.get(t);
            int end = t + 1 < f ? fundamental.get(t + 1) : n;
            int firstNode = start;
            int nodes = end - start;
            int rows = structure[end - 1].length;
            long zero = 0;
            // the previous supernode is this one's last child when its last node's parent is in this one
            while (top >= 0 && parent[first[top] + count[top] - 1] >= start && parent[first[top] + count[top] - 1] < end) {
                long extra = (long) count[top] * (nodes + rows - below[top]);
                long mergedZeros = zeros[top] + zero + extra;
                int mergedNodes = count[top] + nodes;
                double total = mergedNodes * (mergedNodes + 1) / 2.0 + (double) mergedNodes * rows;
                double fraction = mergedZeros / total;
                boolean merge = mergedNodes <= 4 || fraction < 0.05;
                if (!merge) {
                    break;
                }
                firstNode = first[top];
                nodes = mergedNodes;
                zero = mergedZeros;
                top--;
            }
            top++;
            first[top] = firstNode;
            count[top] = nodes;
            below[top] = rows;
            zeros[top] = zero;
        }
        List<Integer> out = new ArrayList<>();
        for (int t = 0; t <= top; t++) {
            out.add(first[t]);
        }
        return out;
    }
}
