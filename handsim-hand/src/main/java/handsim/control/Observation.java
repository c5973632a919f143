package handsim.control;

import handsim.kin.Frame;
import handsim.math.Vec3;
import handsim.sim.RigidState;
import java.util.Arrays;

/**
 * What the controller sees at a tick: time (s), joint angles and rates (model DOF order), the
 * palm centre's world frame and velocity, the object's state, and which bodies of the hand
 * touched the object since the previous tick (the contact joints of sec. 4.1): bit {@code b} of
 * {@code touchedBodies} is set when body {@code b} (model order) touched it.
 */
public record Observation(double time, double[] q, double[] qd, Frame palm, Vec3 palmVelocity, RigidState object,
        long touchedBodies) {

    /** The hand touched the object since the previous tick. */
    public boolean handTouchedObject() {
        return touchedBodies != 0;
    }

    /** The same values throughout, bit for bit (a record's own equals compares the joint arrays by reference). */
    public boolean sameValues(Observation o) {
        return o != null && Double.compare(time, o.time) == 0 && Arrays.equals(q, o.q) && Arrays.equals(qd, o.qd)
                && palm.equals(o.palm) && palmVelocity.equals(o.palmVelocity) && object.equals(o.object)
                && touchedBodies == o.touchedBodies;
    }
}
