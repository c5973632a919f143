package handsim.math;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("fast")
class QuatTest {

    private static final double EPS = 1e-12;

    @Test
    void rotationVectorRoundTrips() {
        SplittableRandom rng = new SplittableRandom(1);
        for (int i = 0; i < 200; i++) {
            Quat q = RandomGeometry.randomRotation(rng);
            Quat back = Quat.fromRotationVector(q.toRotationVector());
            // q and -q are the same rotation
            assertEquals(0, back.angleTo(q), 1e-7);
        }
    }

    @Test
    void rotateMatchesAxisImages() {
        SplittableRandom rng = new SplittableRandom(2);
        for (int i = 0; i < 50; i++) {
            Quat q = RandomGeometry.randomRotation(rng);
            assertEquals(0, q.rotate(Vec3.X).distance(q.xAxis()), EPS);
            assertEquals(0, q.rotate(Vec3.Y).distance(q.yAxis()), EPS);
            assertEquals(0, q.rotate(Vec3.Z).distance(q.zAxis()), EPS);
            assertEquals(0, Quat.fromFrame(q.xAxis(), q.yAxis(), q.zAxis()).angleTo(q), 1e-7);
        }
    }

    @Test
    void betweenTakesFromOntoTo() {
        SplittableRandom rng = new SplittableRandom(3);
        for (int i = 0; i < 50; i++) {
            Vec3 a = RandomGeometry.randomUnit(rng), b = RandomGeometry.randomUnit(rng);
            assertEquals(0, Quat.between(a, b).rotate(a).distance(b), 1e-9);
        }
        assertEquals(0, Quat.between(Vec3.X, Vec3.X.negate()).rotate(Vec3.X).distance(Vec3.X.negate()), 1e-9);
    }

    @Test
    void slerpHitsEndpointsKeepsUnitNormAndConstantSpeed() {
        SplittableRandom rng = new SplittableRandom(4);
        for (int i = 0; i < 50; i++) {
            Quat a = RandomGeometry.randomRotation(rng), b = RandomGeometry.randomRotation(rng);
            assertEquals(0, a.slerp(b, 0).angleTo(a), 1e-7);
            assertEquals(0, a.slerp(b, 1).angleTo(b), 1e-7);
            double total = a.angleTo(b);
            for (double s = 0; s <= 1; s += 0.125) {
                Quat m = a.slerp(b, s);
                assertEquals(1, m.norm(), 1e-12);
                // SLERP moves at constant angular speed along the shorter arc
                assertEquals(s * total, a.angleTo(m), 1e-6);
            }
        }
    }
}
