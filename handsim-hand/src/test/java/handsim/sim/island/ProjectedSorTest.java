package handsim.sim.island;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The sweep's sparse sums leave out a row's zero terms; they must give the dense sum's bits, so
 * that the step's results do not depend on them (ProjectedSor's class comment).
 */
@Tag("fast")
class ProjectedSorTest {

    /** The zeros each kind assumes (indices into one body's 6 numbers). */
    private static final int[][] ZEROS = {{}, {0, 1, 2}, {1, 2, 3}, {0, 2, 4}, {0, 1, 5}};

    @Test
    void everyKindSumsAsTheDenseSum() {
        SplittableRandom rng = new SplittableRandom(11);
        double[] d = new double[6];
        double[] x = new double[6];
        for (int kind = ProjectedSor.DENSE; kind <= ProjectedSor.ANCHOR_Z; kind++) {
            for (int n = 0; n < 100_000; n++) {
                for (int i = 0; i < 6; i++) {
                    // magnitudes over many scales, so that roundings differ between orders
                    d[i] = rng.nextDouble(-1, 1) * Math.scalb(1.0, rng.nextInt(-20, 20));
                    x[i] = rng.nextDouble(-1, 1) * Math.scalb(1.0, rng.nextInt(-20, 20));
                    if (rng.nextInt(8) == 0) {
                        d[i] = 0; // further zeros any kind may meet
                    }
                }
                for (int z : ZEROS[kind]) {
                    d[z] = 0;
                }
                // a row with J2 = -J1, as a joint's: classified by a kind whose zeros it has
                double[] row = new double[ConstraintRows.STRIDE];
                for (int i = 0; i < 6; i++) {
                    row[ConstraintRows.J1 + i] = d[i];
                    row[ConstraintRows.J2 + i] = -d[i];
                }
                int found = ProjectedSor.kind(row, 0, true);
                for (int z : ZEROS[found]) {
                    assertEquals(0, d[z], "kind " + found + " found for a row without its zeros");
                }
                assertTrue(kind == ProjectedSor.DENSE || found != ProjectedSor.DENSE, "a sparse row found dense");
                double dense = ProjectedSor.dot(ProjectedSor.DENSE, d, 0, x[0], x[1], x[2], x[3], x[4], x[5]);
                for (int k : new int[] {kind, found}) {
                    double sparse = ProjectedSor.dot(k, d, 0, x[0], x[1], x[2], x[3], x[4], x[5]);
                    // a zero's sign is the only freedom: 0.0 == -0.0
                    assertEquals(dense == 0 ? 0 : Double.doubleToRawLongBits(dense), sparse == 0 ? 0 : Double.doubleToRawLongBits(sparse),
                            "kind " + k + ": " + sparse + " against the dense " + dense);
                }
            }
        }
    }
}
