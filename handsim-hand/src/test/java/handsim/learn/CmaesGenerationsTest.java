package handsim.learn;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.function.ToDoubleFunction;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * CMA-ES a generation at a time gives {@link Cmaes#minimize}'s result bit for bit: the point,
 * its value and the evaluations made, whatever order a generation's values are computed in, for
 * budgets that end in the middle of a generation, for populations given and default, and for a
 * flat objective on which the optimizer stops early.
 */
@Tag("fast")
class CmaesGenerationsTest {

    /** Drives a minimisation of {@code f} a generation at a time, evaluating each generation's points in reverse order. */
    private static Cmaes.Result drive(ToDoubleFunction<double[]> f, Cmaes.Problem settings, List<Integer> generationSizes) {
        CmaesGenerations g = new CmaesGenerations(settings);
        for (List<double[]> points = g.next(); !points.isEmpty(); points = g.next()) {
            generationSizes.add(points.size());
            double[] values = new double[points.size()];
            List<Integer> order = new ArrayList<>();
            for (int j = 0; j < values.length; j++) {
                order.add(j);
            }
            Collections.reverse(order); // an executor may finish them in any order
            for (int j : order) {
                values[j] = f.applyAsDouble(points.get(j));
            }
            g.tell(values);
        }
        return g.result();
    }

    private static void assertSame(ToDoubleFunction<double[]> f, double[] x0, double sigma, int population, int budget, long seed,
            int expectedLambda) {
        double[] s = CmaesTest.fill(sigma);
        Cmaes.Result direct = Cmaes.minimize(f, x0, s, CmaesTest.fill(-1), CmaesTest.fill(1), population, budget, seed);
        List<Integer> sizes = new ArrayList<>();
        Cmaes.Result stepped = drive(f, new Cmaes.Problem(null, x0, s, CmaesTest.fill(-1), CmaesTest.fill(1), population, budget, seed),
                sizes);
        assertArrayEquals(direct.point(), stepped.point(), 0.0, "the best point, bit for bit");
        assertEquals(Double.doubleToRawLongBits(direct.value()), Double.doubleToRawLongBits(stepped.value()), "its value");
        assertEquals(direct.evaluations(), stepped.evaluations(), "the evaluations made");
        assertEquals(1, sizes.get(0), "the start point comes first, alone");
        for (int i = 1; i < sizes.size() - 1; i++) {
            assertEquals(expectedLambda, sizes.get(i), "a generation is λ points");
        }
        assertEquals(direct.evaluations(), sizes.stream().mapToInt(Integer::intValue).sum(), "every evaluation was asked for once");
    }

    @Test
    void aGenerationAtATimeIsTheDirectMinimisationBitForBit() {
        double[] c = {0.3, -0.5, 0.1, 0.7, -0.2, 0.4, -0.6};
        // default λ = 4 + floor(3 ln 7) = 9; 100 evaluations = the start point, 11 generations of 9 (99 points)
        assertSame(CmaesTest.ellipsoid(c), CmaesTest.fill(0), 0.2, 0, 100, 100000, 9);
        // a budget that ends in the middle of a generation: 1 + 5 * 12 + 7
        assertSame(CmaesTest.ellipsoid(c), CmaesTest.fill(0.1), 0.3, 12, 68, 7, 12);
        // a bumpy objective, several seeds
        ToDoubleFunction<double[]> bumpy = x -> {
            double f = 0;
            for (double v : x) {
                f += v * v - 0.3 * Math.cos(9 * v);
            }
            return f;
        };
        for (long seed = 1; seed <= 3; seed++) {
            assertSame(bumpy, CmaesTest.fill(0.5), 0.2, 0, 150, seed, 9);
        }
    }

    @Test
    void aFlatObjectiveEndsAsTheDirectMinimisationDoes() {
        ToDoubleFunction<double[]> flat = x -> 1.0;
        List<Integer> sizes = new ArrayList<>();
        Cmaes.Problem settings = new Cmaes.Problem(null, CmaesTest.fill(0), CmaesTest.fill(0.2), CmaesTest.fill(-1), CmaesTest.fill(1), 0,
                1000, 5);
        Cmaes.Result stepped = drive(flat, settings, sizes);
        Cmaes.Result direct = Cmaes.minimize(flat, CmaesTest.fill(0), CmaesTest.fill(0.2), CmaesTest.fill(-1), CmaesTest.fill(1), 0, 1000, 5);
        assertEquals(direct.evaluations(), stepped.evaluations());
        assertTrue(direct.evaluations() < 1000, "commons-math stops on flat fitness before the budget: " + direct.evaluations());
        assertArrayEquals(direct.point(), stepped.point(), 0.0);
    }
}
