package handsim.control;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.Inertia;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** Torque-free rotation against the closed-form motions of a round body and a symmetric top. */
@Tag("fast")
class FreeRotationTest {

    @Test
    void aRoundBodyTurnsAtItsConstantAngularVelocity() {
        // equal principal moments: w = L / I stays constant, so q(t) = exp(w t) q0 exactly;
        // only rounding over ~1000 steps separates the two (1e-9 on the turned axes)
        FreeRotation round = new FreeRotation(Inertia.diagonal(0.02, 0.02, 0.02));
        Quat q0 = Quat.fromAxisAngle(new Vec3(1, 2, 3).normalized(), 0.7);
        Vec3 w = new Vec3(3, -8, 5);
        FreeRotation.Spin s = round.after(q0, w, 0.5);
        Quat expected = Quat.fromRotationVector(w.times(0.5)).mul(q0);
        for (Vec3 e : new Vec3[] {Vec3.X, Vec3.Y, Vec3.Z}) {
            assertEquals(0, s.orientation().rotate(e).distance(expected.rotate(e)), 1e-9, "orientation");
        }
        assertEquals(0, s.angularVelocity().distance(w), 1e-9, "angular velocity");
    }

    @Test
    void aSymmetricTopsAxisPrecessesAboutItsAngularMomentum() {
        // a club-like body (axis y, axial moment a tenth of the transverse one) rolling at 25 rad/s
        // about its axis and tumbling at 10 rad/s across it: torque-free, the axis turns about the
        // constant angular momentum L at |L| / I_transverse (Landau & Lifshitz sec. 33), not about
        // w at |w|; the midpoint rule in 0.5 ms steps keeps within 1e-3 rad over 0.6 s (2e-4
        // measured; a catch cares about degrees)
        double transverse = 1e-3, axial = 1e-4;
        FreeRotation top = new FreeRotation(Inertia.diagonal(transverse, axial, transverse));
        Quat q0 = Quat.fromAxisAngle(Vec3.X, 0.3);
        Vec3 axis0 = q0.rotate(Vec3.Y);
        Vec3 w0 = axis0.times(25).plus(q0.rotate(Vec3.Z).times(10));
        Vec3 l = axis0.times(axial * 25).plus(q0.rotate(Vec3.Z).times(transverse * 10));
        double t = 0.6;
        Vec3 expected = Quat.fromAxisAngle(l.normalized(), l.norm() / transverse * t).rotate(axis0);

        FreeRotation.Spin s = top.after(q0, w0, t);

        assertEquals(0, s.orientation().rotate(Vec3.Y).distance(expected), 1e-3, "long axis");
        Vec3 lAfter = s.orientation().rotate(Inertia.diagonal(transverse, axial, transverse)
                .times(s.orientation().inverseRotate(s.angularVelocity())));
        assertEquals(0, lAfter.distance(l), 1e-9, "angular momentum conserved");
        // turning the axis by the whole angular velocity would miss it by far (a constant-angular-velocity prediction)
        double naiveMiss = Quat.fromRotationVector(w0.times(t)).rotate(axis0).distance(expected);
        assertTrue(naiveMiss > 0.5, "constant-w prediction misses by " + naiveMiss);
    }
}
