package handsim.control;

import handsim.kin.Frame;
import handsim.math.Vec3;
import handsim.sim.RigidState;

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
}
