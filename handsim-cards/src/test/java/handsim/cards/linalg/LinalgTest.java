package handsim.cards.linalg;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;
import java.util.TreeSet;
import org.apache.commons.math3.linear.CholeskyDecomposition;
import org.apache.commons.math3.linear.MatrixUtils;
import org.apache.commons.math3.linear.RealMatrix;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** Small dense and sparse linear algebra of the card simulator, each against its definition. */
@Tag("fast")
class LinalgTest {

    @Test
    void jacobiEigenpairsReconstructTheMatrixAndProjectionClipsOnlyNegatives() {
        Random rng = new Random(3);
        SymmetricEigen eig = new SymmetricEigen(12);
        for (int n : new int[] {3, 6, 9, 12}) {
            double[] m = new double[n * n];
            for (int i = 0; i < n; i++) {
                for (int j = 0; j <= i; j++) {
                    double v = rng.nextGaussian();
                    m[i * n + j] = v;
                    m[j * n + i] = v;
                }
            }
            eig.decompose(m, n);
            // A v = λ v for every pair, to 1e-12 of the matrix scale
            for (int e = 0; e < n; e++) {
                for (int i = 0; i < n; i++) {
                    double av = 0;
                    for (int j = 0; j < n; j++) {
                        av += m[i * n + j] * eig.vector(e, j);
                    }
                    assertEquals(eig.value(e) * eig.vector(e, i), av, 1e-11);
                }
            }
            double[] p = m.clone();
            eig.projectToPsd(p, n);
            SymmetricEigen check = new SymmetricEigen(12);
            check.decompose(p, n);
            for (int e = 0; e < n; e++) {
                assertTrue(check.value(e) > -1e-11, "projected eigenvalue " + check.value(e));
            }
        }
    }

    @Test
    void rotationVariantSvdReconstructsAndFlagsInversion() {
        Random rng = new Random(5);
        Svd3 svd = new Svd3();
        for (int trial = 0; trial < 200; trial++) {
            double[] f = new double[9];
            for (int i = 0; i < 9; i++) {
                f[i] = rng.nextGaussian();
            }
            if (trial % 50 == 0) {
                f = new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1};
            }
            svd.decompose(f);
            assertEquals(1, Svd3.det(svd.u), 1e-12, "U is a rotation");
            assertEquals(1, Svd3.det(svd.v), 1e-12, "V is a rotation");
            assertEquals(Math.signum(Svd3.det(f)), Math.signum(svd.sigma[2]), "sigma3 carries det F's sign");
            assertTrue(svd.sigma[0] >= svd.sigma[1] && svd.sigma[1] >= Math.abs(svd.sigma[2]) - 1e-12);
            for (int r = 0; r < 3; r++) {
                for (int c = 0; c < 3; c++) {
                    double v = 0;
                    for (int k = 0; k < 3; k++) {
                        v += svd.u[r * 3 + k] * svd.sigma[k] * svd.v[c * 3 + k];
                    }
                    assertEquals(f[r * 3 + c], v, 1e-12);
                }
            }
        }
    }

    @Test
    void sparseFactorisationsSolveLikeADenseCholeskyAndReuseTheirPattern() {
        // ojAlgo's QDLDL, handsim's supernodal LLᵀ on one thread and on two
        solvesLikeADenseCholesky(SparseSpdSystem.Factorisation.QDLDL, false);
        solvesLikeADenseCholesky(SparseSpdSystem.Factorisation.SUPERNODAL, false);
        solvesLikeADenseCholesky(SparseSpdSystem.Factorisation.SUPERNODAL, true);
    }

    private static void solvesLikeADenseCholesky(SparseSpdSystem.Factorisation factorisation, boolean parallel) {
        Random rng = new Random(11);
        int nodes = 40;
        TreeSet<Long> keys = new TreeSet<>();
        for (int k = 0; k < 90; k++) {
            int a = rng.nextInt(nodes);
            int b = rng.nextInt(nodes);
            if (a != b) {
                keys.add(SparseSpdSystem.pairKey(a, b));
            }
        }
        long[] pairs = keys.stream().mapToLong(Long::longValue).toArray();
        SparseSpdSystem sys = new SparseSpdSystem(nodes, factorisation, parallel);
        assertTrue(sys.setPattern(pairs));
        assertFalse(sys.setPattern(pairs.clone()), "an unchanged pattern is kept");
        for (int round = 0; round < 2; round++) {
            RealMatrix dense = MatrixUtils.createRealMatrix(3 * nodes, 3 * nodes);
            sys.clear();
            for (long key : pairs) {
                int a = (int) (key >>> 32);
                int b = (int) key;
                double[] block = new double[9];
                for (int i = 0; i < 9; i++) {
                    block[i] = rng.nextGaussian() * 0.1;
                }
                sys.addBlock(a, b, block, 0, 3);
                for (int r = 0; r < 3; r++) {
                    for (int c = 0; c < 3; c++) {
                        dense.addToEntry(3 * a + r, 3 * b + c, block[r * 3 + c]);
                        dense.addToEntry(3 * b + c, 3 * a + r, block[r * 3 + c]);
                    }
                }
            }
            for (int a = 0; a < nodes; a++) {
                double[] diag = {2, 0.3, -0.1, 0.3, 2.5, 0.2, -0.1, 0.2, 3};
                sys.addBlock(a, a, diag, 0, 3);
                sys.addDiagonal(a, 10);
                for (int r = 0; r < 3; r++) {
                    for (int c = 0; c < 3; c++) {
                        dense.addToEntry(3 * a + r, 3 * a + c, diag[r * 3 + c] + (r == c ? 10 : 0));
                    }
                }
            }
            assertTrue(sys.factor());
            double[] b = new double[3 * nodes];
            for (int i = 0; i < b.length; i++) {
                b[i] = rng.nextGaussian();
            }
            double[] expected = new CholeskyDecomposition(dense).getSolver().solve(MatrixUtils.createRealVector(b)).toArray();
            double[] x = b.clone();
            sys.solve(x, new double[3 * nodes]);
            for (int i = 0; i < x.length; i++) {
                assertEquals(expected[i], x[i], 1e-10, factorisation + ": solution entry " + i + " in round " + round);
            }
        }
        assertEquals(1, sys.patternBuilds());
        assertTrue(Arrays.stream(pairs).allMatch(k -> k >= 0));
    }
}
