package handsim.sim.island;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The sweeps before the first shuffle take the rows level by level rather than in their packed
 * order (rows without a friction index first, each group in assembly order). That must not change
 * a bit: a Gauss-Seidel row reads and writes only its own bodies' fc, so the two orders agree as
 * long as every two rows that share a body keep their packed order (ProjectedSor's class comment).
 */
@Tag("fast")
class SweepOrderTest {

    @Test
    void rowsThatShareABodyKeepTheirPackedOrder() {
        SplittableRandom rng = new SplittableRandom(5);
        int bodies = 9;
        int reordered = 0;
        for (int trial = 0; trial < 200; trial++) {
            ConstraintRows rows = new ConstraintRows(16);
            int m = 1 + rng.nextInt(120);
            List<Integer> normals = new ArrayList<>();
            for (int i = 0; i < m; i++) {
                int b1 = rng.nextInt(bodies);
                int b2 = rng.nextInt(4) == 0 ? -1 : (b1 + 1 + rng.nextInt(bodies - 1)) % bodies;
                if (!normals.isEmpty() && rng.nextInt(3) == 0) {
                    // a friction row: on its normal row's bodies, bounded by its impulse
                    int normal = normals.get(rng.nextInt(normals.size()));
                    rows.add(rows.body1[normal], rows.body2[normal], 0);
                    rows.findex[i] = normal;
                } else {
                    rows.add(b1, b2, 0);
                    normals.add(i);
                }
            }
            int[] packed = packedOrder(rows, m);
            int[] swept = new ProjectedSor(bodies).firstSweepOrder(rows, 0, m);
            int[] rank = new int[m];
            boolean[] seen = new boolean[m];
            for (int k = 0; k < m; k++) {
                assertTrue(!seen[swept[k]], "row " + swept[k] + " swept twice");
                seen[swept[k]] = true;
                rank[swept[k]] = k;
            }
            for (int p = 0; p < m; p++) {
                for (int q = p + 1; q < m; q++) {
                    int i = packed[p], j = packed[q];
                    if (shareABody(rows, i, j)) {
                        assertTrue(rank[i] < rank[j], "rows " + i + " and " + j + " share a body and swap (trial " + trial + ")");
                    } else if (rank[i] > rank[j]) {
                        reordered++;
                    }
                }
            }
        }
        // the level order does move independent rows, else it would gain nothing
        assertTrue(reordered > 0, "no independent rows reordered");
    }

    @Test
    void aChainKeepsItsOrderAndTwoChainsInterleave() {
        // two chains hanging from the world, 0-1-2 and 3-4-5, one row per joint: levels 0, 1, 2 each
        ConstraintRows rows = new ConstraintRows(16);
        int[][] joints = {{0, -1}, {1, 0}, {2, 1}, {3, -1}, {4, 3}, {5, 4}};
        for (int[] j : joints) {
            rows.add(j[0], j[1], 0);
        }
        int[] swept = new ProjectedSor(6).firstSweepOrder(rows, 0, joints.length);
        assertEquals(List.of(0, 3, 1, 4, 2, 5), List.of(swept[0], swept[1], swept[2], swept[3], swept[4], swept[5]));
    }

    /** Rows without a friction index first, then the friction rows, each in assembly order. */
    private static int[] packedOrder(ConstraintRows rows, int m) {
        int[] out = new int[m];
        int n = 0;
        for (int pass = 0; pass < 2; pass++) {
            for (int i = 0; i < m; i++) {
                if ((rows.findex[i] >= 0) == (pass == 1)) {
                    out[n++] = i;
                }
            }
        }
        return out;
    }

    private static boolean shareABody(ConstraintRows rows, int i, int j) {
        int a = rows.body1[i], b = rows.body2[i];
        int c = rows.body1[j], d = rows.body2[j];
        return a == c || a == d || (b >= 0 && (b == c || b == d));
    }
}
