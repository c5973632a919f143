package handsim.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * ArcTangent promises StrictMath's bits (fdlibm's), so that the constrained step may call it in
 * place of Math.atan2 without changing a single result: every case is compared bit for bit.
 */
@Tag("fast")
class ArcTangentTest {

    private static void assertSameBits(double y, double x) {
        double expected = StrictMath.atan2(y, x);
        double actual = ArcTangent.atan2(y, x);
        if (Double.isNaN(expected)) {
            // a NaN's payload is the platform's; only NaN-ness is specified
            assertTrue(Double.isNaN(actual), () -> "atan2(" + y + ", " + x + ")");
            return;
        }
        assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(actual),
                () -> "atan2(" + y + ", " + x + "): " + actual + " against StrictMath's " + expected);
    }

    @Test
    void specialValuesAndBranchBoundaries() {
        // zeros, infinities, NaN, the ends of the range, and fdlibm's interval ends 7/16, 11/16,
        // 19/16, 39/16 and their neighbours
        double[] special = {0.0, -0.0, 1.0, -1.0, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NaN,
            Double.MIN_VALUE, -Double.MIN_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE, 1e-300, 1e300, 0x1p-29, 0x1p66,
            0.4375, 0.6875, 1.1875, 2.4375, Math.nextDown(0.4375), Math.nextUp(2.4375), Math.nextUp(1.0), Math.nextDown(1.0)};
        for (double y : special) {
            for (double x : special) {
                assertSameBits(y, x);
                assertSameBits(-y, x);
            }
        }
    }

    @Test
    void randomArgumentsOfEveryScale() {
        SplittableRandom rng = new SplittableRandom(7);
        for (int i = 0; i < 400_000; i++) {
            switch (i % 4) {
                case 0 -> assertSameBits(rng.nextDouble(-1, 1), rng.nextDouble(-1, 1));
                // a joint near its zero angle: the half angle's sine and cosine
                case 1 -> assertSameBits(Math.sqrt(rng.nextDouble()) * 1e-3, 1 - rng.nextDouble() * 1e-6);
                case 2 -> assertSameBits(Double.longBitsToDouble(rng.nextLong()), Double.longBitsToDouble(rng.nextLong()));
                default -> {
                    double t = rng.nextDouble(-Math.PI, Math.PI);
                    assertSameBits(Math.sin(t) * Math.scalb(1.0, rng.nextInt(-80, 80)), Math.cos(t));
                }
            }
        }
    }
}
