package handsim.cards.tpe;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The random half of the sampler (draws from l(x)), which cannot be compared with Optuna's
 * numbers, checked against the estimator's own density, which is (TpeReferenceTest).
 */
@Tag("fast")
class ParzenEstimatorTest {

    @Test
    void truncatedNormalQuantilesInvertTheMassEvenInFarTails() {
        // mass(a, x) / mass(a, b) = q at x = quantile(q), to 1e-9 relative, on [-40, -30] and [30, 40] too
        double[][] bounds = {{-1, 1}, {5, 7}, {-40, -30}, {30, 40}, {2, 2.5}, {-0.5, 8}};
        for (double[] ab : bounds) {
            for (double q : new double[] {1e-3, 0.3, 0.5, 0.9, 0.999}) {
                double x = TruncatedNormal.quantile(q, ab[0], ab[1]);
                assertTrue(x >= ab[0] && x <= ab[1], "quantile " + q + " of " + Arrays.toString(ab) + ": " + x);
                double share = Math.exp(TruncatedNormal.logMass(ab[0], x) - TruncatedNormal.logMass(ab[0], ab[1]));
                assertEquals(q, share, 1e-9 * q, "share below the " + q + " quantile of " + Arrays.toString(ab));
            }
        }
    }

    @Test
    void drawsFollowTheMixtureDensity() {
        // l(x) on [0, 1] from observations near both ends and the middle, with unequal weights,
        // prior included: its density (exp of logPdf) integrates to 1, and 20,000 draws have a
        // Kolmogorov-Smirnov distance to its CDF below 0.0138, the 0.1 % critical value
        // 1.95 / sqrt(20,000) (measured 0.0069)
        Param x = Param.uniform("x", 0, 1);
        ParzenEstimator l = ParzenEstimator.fit(new double[] {0.02, 0.5, 0.97, 0.55}, new double[] {1, 0.3, 1, 0.6}, x, TpeSettings.OPTUNA_DEFAULTS);
        int grid = 20_000;
        double[] cdf = new double[grid + 1];
        for (int i = 1; i <= grid; i++) { // trapezoid rule
            cdf[i] = cdf[i - 1] + 0.5 * (Math.exp(l.logPdf((i - 1.0) / grid)) + Math.exp(l.logPdf((double) i / grid))) / grid;
        }
        assertEquals(1.0, cdf[grid], 1e-6, "the density integrates to 1");
        SplittableRandom rng = new SplittableRandom(1);
        double[] draws = new double[20_000];
        for (int i = 0; i < draws.length; i++) {
            draws[i] = l.sample(rng);
        }
        Arrays.sort(draws);
        double ks = 0;
        for (int i = 0; i < draws.length; i++) {
            double f = cdf[(int) Math.min(grid, Math.round(draws[i] * grid))];
            ks = Math.max(ks, Math.max(Math.abs(f - (double) i / draws.length), Math.abs(f - (i + 1.0) / draws.length)));
        }
        System.out.printf("KS distance of 20,000 draws from l(x): %.4f%n", ks);
        assertTrue(ks < 0.0138, "KS distance " + ks);
    }

    @Test
    void integerDrawsFollowTheGridCellMasses() {
        // an integer in [0, 6]: the cell masses (exp of logPdf) sum to 1 and 30,000 draws hit each
        // integer within 4 binomial standard deviations of its mass
        Param k = Param.integer("k", 0, 6);
        ParzenEstimator l = ParzenEstimator.fit(new double[] {0, 1, 1, 5}, new double[] {1, 1, 1, 1}, k, TpeSettings.OPTUNA_DEFAULTS);
        double[] mass = new double[7];
        for (int v = 0; v <= 6; v++) {
            mass[v] = Math.exp(l.logPdf(v));
        }
        assertEquals(1.0, Arrays.stream(mass).sum(), 1e-12, "cell masses sum to 1");
        int n = 30_000;
        int[] hits = new int[7];
        SplittableRandom rng = new SplittableRandom(2);
        for (int i = 0; i < n; i++) {
            double v = l.sample(rng);
            assertEquals(Math.rint(v), v, 0.0, "on the grid");
            hits[(int) v]++;
        }
        for (int v = 0; v <= 6; v++) {
            double sd = Math.sqrt(n * mass[v] * (1 - mass[v]));
            assertEquals(n * mass[v], hits[v], 4 * sd, "draws of " + v);
        }
    }
}
