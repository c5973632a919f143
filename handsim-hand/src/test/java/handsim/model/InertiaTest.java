package handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;

import handsim.math.Quat;
import handsim.math.Vec3;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The tensor's product with a vector and its inverse, on a full (rotated, off-diagonal) tensor. */
@Tag("fast")
class InertiaTest {

    @Test
    void solveUndoesTimesForAFullTensor() {
        // a club-like diagonal tensor turned off its axes has every off-diagonal entry; solving
        // for the spin of its angular momentum gives the spin back (rounding only: 1e-12 relative)
        Inertia tensor = Inertia.diagonal(1e-3, 1e-4, 1.2e-3).rotated(Quat.fromAxisAngle(new Vec3(1, -2, 0.5).normalized(), 0.9));
        Vec3 w = new Vec3(3, -25, 10);
        Vec3 l = tensor.times(w);
        assertEquals(0, tensor.solve(l).distance(w), 1e-12 * w.norm());
        // times: about a principal axis, L = I w along it
        Vec3 principal = Quat.fromAxisAngle(new Vec3(1, -2, 0.5).normalized(), 0.9).rotate(Vec3.Y);
        assertEquals(0, tensor.times(principal).distance(principal.times(1e-4)), 1e-15);
    }
}
