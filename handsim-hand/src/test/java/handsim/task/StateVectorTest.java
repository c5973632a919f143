package handsim.task;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.control.Observation;
import handsim.kin.Frame;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.sim.RigidState;
import java.util.Optional;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("fast")
class StateVectorTest {

    private static final Vec3 CAN_AXIS = new Vec3(0, 0, 1);
    private static final double[] GOAL = {1.2};

    private static Observation observation(Quat palm, Quat object) {
        RigidState o = new RigidState(new Vec3(0.1, 0.6, 0.35), object, Vec3.ZERO, Vec3.ZERO);
        return new Observation(0, new double[0], new double[0], new Frame(new Vec3(0.05, 0.62, 0.33), palm), Vec3.ZERO, o, 0);
    }

    private static double distance(double[] a, double[] b) {
        double d = 0;
        for (int i = 0; i < a.length; i++) {
            d = Math.max(d, Math.abs(a[i] - b[i]));
        }
        return d;
    }

    @Test
    void aPalmTurnedNearlyHalfATurnHasAContinuousStateOnlyInTheContinuousEncoding() {
        // the neutral palm is turned almost exactly pi (its rotation vector measured 3.1409 rad):
        // 1e-3 rad either side of pi is the same palm to the eye, 2e-3 rad of rotation apart
        Vec3 axis = new Vec3(-0.766, 0, -0.643).normalized();
        Quat below = Quat.fromAxisAngle(axis, Math.PI - 1e-3), above = Quat.fromAxisAngle(axis, Math.PI + 1e-3);
        StateVector paper = new StateVector(StateVector.Encoding.PAPER, Optional.of(CAN_AXIS));
        StateVector continuous = new StateVector(StateVector.Encoding.CONTINUOUS, Optional.of(CAN_AXIS));
        Observation a = observation(below, Quat.IDENTITY), b = observation(above, Quat.IDENTITY);
        // the rotation vector jumps to its opposite: about 2 pi |axis component| apart
        assertTrue(distance(paper.encode(a, GOAL), paper.encode(b, GOAL)) > 4, "paper encoding jumps");
        // matrix columns move by at most the rotation between them (2e-3 rad) times 2 (|sin| bound, both columns)
        assertTrue(distance(continuous.encode(a, GOAL), continuous.encode(b, GOAL)) < 4e-3, "continuous encoding does not");
    }

    @Test
    void aCanEndForEndOrSpunAboutItsAxisGivesTheSameState() {
        StateVector s = new StateVector(StateVector.Encoding.CONTINUOUS, Optional.of(CAN_AXIS));
        Quat palm = Quat.fromAxisAngle(new Vec3(0.3, 1, -0.2).normalized(), 2.0);
        Quat can = Quat.fromAxisAngle(new Vec3(1, 0.4, 0.1).normalized(), 0.7);
        double[] x = s.encode(observation(palm, can), GOAL);
        // a half turn about an axis across the can turns it end for end: the same can (exact up to rounding)
        double[] flipped = s.encode(observation(palm, can.mul(Quat.fromAxisAngle(new Vec3(1, 0, 0), Math.PI))), GOAL);
        double[] spun = s.encode(observation(palm, can.mul(Quat.fromAxisAngle(CAN_AXIS, 1.3))), GOAL);
        assertArrayEquals(x, flipped, 1e-12);
        assertArrayEquals(x, spun, 1e-12);
        assertEquals(19, x.length, "18 entries and the goal");
        assertEquals(1.2, x[18], 0);
        // the dyad of a unit axis has trace 1
        assertEquals(1, x[12] + x[13] + x[14], 1e-12);
    }

    @Test
    void theDyadIsTheAxisInThePalmFrame() {
        StateVector s = new StateVector(StateVector.Encoding.CONTINUOUS, Optional.of(CAN_AXIS));
        // palm turned a quarter turn about world y: its x axis is world -z, so a can along world z lies along palm -x
        Quat palm = Quat.fromAxisAngle(new Vec3(0, 1, 0), Math.PI / 2);
        double[] x = s.encode(observation(palm, Quat.IDENTITY), GOAL);
        assertArrayEquals(new double[] {1, 0, 0, 0, 0, 0}, java.util.Arrays.copyOfRange(x, 12, 18), 1e-12);
        assertArrayEquals(new double[] {0, 0, -1}, java.util.Arrays.copyOfRange(x, 3, 6), 1e-12, "palm x axis in world");
    }

    @Test
    void aSphereHasNoOrientationInTheContinuousState() {
        StateVector s = new StateVector(StateVector.Encoding.CONTINUOUS, Optional.empty());
        double[] x = s.encode(observation(Quat.IDENTITY, Quat.fromAxisAngle(new Vec3(0, 1, 0), 1)), GOAL);
        assertArrayEquals(new double[6], java.util.Arrays.copyOfRange(x, 12, 18), 0);
    }

    @Test
    void theExtendedStateAddsTheObjectsMotionInThePalmFrameTheJointAnglesAndTheTouchingBodies() {
        StateVector.Hand hand = new StateVector.Hand(3, 5);
        StateVector s = new StateVector(StateVector.Encoding.EXTENDED, Optional.of(CAN_AXIS), hand);
        StateVector continuous = new StateVector(StateVector.Encoding.CONTINUOUS, Optional.of(CAN_AXIS));
        // palm a quarter turn about world y: palm x is world -z, palm z world x, palm y world y
        Quat palm = Quat.fromAxisAngle(new Vec3(0, 1, 0), Math.PI / 2);
        RigidState can = new RigidState(new Vec3(0.1, 0.6, 0.35), Quat.IDENTITY, new Vec3(0, 0, 2), new Vec3(3, 0, 0));
        long touching = 0b10010; // bodies 1 and 4
        Observation obs = new Observation(0, new double[] {0.1, -0.2, 0.3}, new double[3], new Frame(new Vec3(0.05, 0.62, 0.33), palm),
                Vec3.ZERO, can, touching);
        double[] x = s.encode(obs, GOAL);
        assertEquals(18 + 6 + 3 + 5 + 1, x.length, "continuous, object motion, 3 joints, 5 bodies, the goal");
        assertEquals(x.length - 1, s.size(0));
        assertArrayEquals(continuous.encode(obs, new double[0]), java.util.Arrays.copyOfRange(x, 0, 18), 0,
                "the extended state begins with the continuous one");
        // world velocity (0, 0, 2) along world z is palm -x; angular velocity about world x is about palm z
        assertArrayEquals(new double[] {-2, 0, 0}, java.util.Arrays.copyOfRange(x, 18, 21), 1e-12);
        assertArrayEquals(new double[] {0, 0, 3}, java.util.Arrays.copyOfRange(x, 21, 24), 1e-12);
        assertArrayEquals(new double[] {0.1, -0.2, 0.3}, java.util.Arrays.copyOfRange(x, 24, 27), 0);
        assertArrayEquals(new double[] {0, 1, 0, 0, 1}, java.util.Arrays.copyOfRange(x, 27, 32), 0);
        assertEquals(1.2, x[32], 0);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new StateVector(StateVector.Encoding.EXTENDED, Optional.of(CAN_AXIS)));
        assertTrue(e.getMessage().contains("joint and body counts"), e.getMessage());
    }

    @Test
    void encodingsAreNamedInConfigs() {
        assertEquals(StateVector.Encoding.CONTINUOUS, StateVector.Encoding.parse("continuous"));
        assertEquals(StateVector.Encoding.PAPER, StateVector.Encoding.parse("paper"));
        assertEquals(StateVector.Encoding.EXTENDED, StateVector.Encoding.parse("extended"));
        assertEquals(StateVector.Encoding.PAPER, StateVector.Encoding.parse("PAPER"), "the enum's own name reads back too");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> StateVector.Encoding.parse("euler"));
        assertTrue(e.getMessage().contains("euler"), e.getMessage());
    }
}
