package handsim.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("fast")
class HermiteTest {

    private final Hermite h = new Hermite(new Vec3(0.1, 0.6, 0.3), new Vec3(1, -2, 0.5), new Vec3(0.0, 0.9, 0.4),
            new Vec3(0, 3, 0), 0.25);

    @Test
    void endpointsAndEndVelocitiesAreThoseOfEquation1() {
        assertEquals(0, h.position(0).distance(h.p0()), 1e-15);
        assertEquals(0, h.position(0.25).distance(h.p1()), 1e-15);
        assertEquals(0, h.velocity(0).distance(h.v0()), 1e-12);
        assertEquals(0, h.velocity(0.25).distance(h.v1()), 1e-12);
    }

    @Test
    void velocityIsTheDerivativeOfPosition() {
        double dt = 1e-6;
        for (double t = 0.01; t < 0.24; t += 0.02) {
            Vec3 fd = h.position(t + dt).minus(h.position(t - dt)).times(1 / (2 * dt));
            // central difference error ~ dt^2 * |p'''|
            assertEquals(0, fd.distance(h.velocity(t)), 1e-6);
        }
    }

    @Test
    void heldAtEndPointsOutsideTheInterval() {
        assertEquals(0, h.position(-1).distance(h.p0()), 0);
        assertEquals(0, h.position(2).distance(h.p1()), 0);
        assertThrows(IllegalArgumentException.class, () -> new Hermite(Vec3.ZERO, Vec3.ZERO, Vec3.X, Vec3.ZERO, 0));
    }
}
