package handsim.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.math.Quat;
import handsim.math.RandomGeometry;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** Euler angles in all six orders of three distinct axes: splitting a rotation and composing it again gives it back. */
@Tag("fast")
class EulerTest {

    @Test
    void decomposeThenComposeIsTheIdentityInEveryOrder() {
        int[][] orders = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
        SplittableRandom rng = new SplittableRandom(7);
        for (int[] order : orders) {
            for (int i = 0; i < 200; i++) {
                Quat q = RandomGeometry.randomRotation(rng);
                double[] a = Euler.decompose(q, order);
                assertTrue(Math.abs(a[1]) <= Math.PI / 2 + 1e-12, "the middle angle in [-90, 90] deg");
                // double round-off only, away from the gimbal lock (|b| = 90 deg) a random rotation almost never nears
                assertEquals(0, Euler.compose(a, order).angleTo(q), 1e-6);
            }
        }
    }

    @Test
    void anglesOfAKnownRotationComeBack() {
        double[] want = {0.3, -0.5, 1.1};
        int[] zxy = {2, 0, 1};
        double[] got = Euler.decompose(Euler.compose(want, zxy), zxy);
        for (int k = 0; k < 3; k++) {
            assertEquals(want[k], got[k], 1e-12);
        }
    }
}
