package handsim.control;

import static org.junit.jupiter.api.Assertions.assertEquals;

import handsim.kin.Frame;
import handsim.math.Hermite;
import handsim.math.Quat;
import handsim.math.Vec3;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** A THROW held open by a closed-loop release goes on past its curve as it ended. */
@Tag("fast")
class PalmTrajectoryTest {

    private final Quat start = Quat.IDENTITY;
    private final Quat end = Quat.fromAxisAngle(Vec3.X, Math.toRadians(-40));
    private final PalmTrajectory throwCurve = new PalmTrajectory(
            new Hermite(Vec3.ZERO, Vec3.ZERO, new Vec3(0, 0.25, 0), new Vec3(0, 3.0, 0), 0.2), start, end);

    @Test
    void withinItsDurationItIsTheCurve() {
        for (double t : new double[] {0, 0.05, 0.2}) {
            Frame a = throwCurve.at(t);
            Frame b = throwCurve.continuedAt(t);
            assertEquals(0, a.origin().distance(b.origin()), 1e-15);
            assertEquals(0, a.rotation().angleTo(b.rotation()), 1e-12);
        }
    }

    @Test
    void pastItsDurationThePalmGoesOnAtItsEndVelocityAndTurnsOnAtItsAverageRate() {
        Frame f = throwCurve.continuedAt(0.25);
        // 0.05 s at the end velocity (0, 3, 0) m/s beyond the end point (0, 0.25, 0)
        assertEquals(0, f.origin().distance(new Vec3(0, 0.40, 0)), 1e-12);
        // 40 deg over 0.2 s turns on by 10 deg in 0.05 s, about the same axis
        Quat expected = Quat.fromAxisAngle(Vec3.X, Math.toRadians(-50));
        assertEquals(0, f.rotation().angleTo(expected), 1e-9);
    }
}
