package handsim.cards.energy;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** Finite-difference checks of the membrane, bending and tetrahedron energies, and their rest states. */
@Tag("fast")
class ElasticEnergiesTest {

    private static double[] perturbed(double[] rest, double amount, long seed) {
        Random rng = new Random(seed);
        double[] x = rest.clone();
        for (int i = 0; i < x.length; i++) {
            x[i] += amount * rng.nextGaussian();
        }
        return x;
    }

    @Test
    void membraneDerivativesMatchFiniteDifferences() {
        double[] rest = {0, 0, 0, 0.01, 0, 0, 0.002, 0.009, 0};
        Membrane m = new Membrane(new int[] {0, 1, 2}, rest, new double[] {3e9}, new double[] {0.3}, new double[] {2.5e-4});
        // unstrained at rest and under rigid motion
        assertEquals(0, m.value(rest), 1e-18);
        for (long seed = 1; seed <= 3; seed++) {
            // 20 % strains, so that compression makes the Hessian indefinite
            FiniteDifference.check(m, perturbed(rest, 0.002, seed), 1e-8, 1e-5);
        }
    }

    @Test
    void bendingDerivativesMatchFiniteDifferences() {
        // hinge x0-x1 with x2 on one side and x3 on the other, flat at rest
        double[] rest = {0, 0, 0, 0.01, 0, 0, 0.004, 0.008, 0, 0.006, -0.007, 0};
        Bending b = new Bending(new int[] {0, 1, 2, 3}, rest, new double[] {1e-3});
        assertEquals(0, b.value(rest), 1e-18);
        for (long seed = 1; seed <= 3; seed++) {
            FiniteDifference.check(b, perturbed(rest, 0.002, seed), 1e-8, 1e-5);
        }
    }

    @Test
    void fixedCorotatedDerivativesMatchFiniteDifferencesIncludingInversion() {
        double[] rest = {0, 0, 0, 0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01};
        TetElasticity t = new TetElasticity(new int[] {0, 1, 2, 3}, rest, new double[] {1.7e6}, new double[] {2.5e6});
        assertEquals(0, t.value(rest), 1e-18);
        for (long seed = 1; seed <= 4; seed++) {
            FiniteDifference.check(t, perturbed(rest, 0.002, seed), 1e-8, 1e-5);
        }
        // an inverted tetrahedron: x3 pushed through the base
        double[] inverted = rest.clone();
        inverted[11] = -0.004;
        inverted[9] = 0.001;
        FiniteDifference.check(t, inverted, 1e-8, 1e-5);
    }
}
