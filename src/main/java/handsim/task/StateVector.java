package handsim.task;

import handsim.control.Observation;
import handsim.kin.Frame;
import handsim.math.Vec3;

/**
 * The learner's state at a THROW decision (paper sec. 3.7): {@code (p_h, r_h, p_p, r_p, goal)},
 * with p_h and r_h the palm centre's position and rotation vector (world), p_p the object's
 * position in the palm frame, r_p the object's rotation vector (world), and the task's goal
 * appended ("we embed the goal to the state vector", sec. 4.2). Rotation vectors are those of the
 * quaternion with w >= 0 (angle at most pi).
 */
public final class StateVector {

    /** Entries before the goal. */
    public static final int BASE_SIZE = 12;

    private StateVector() {
    }

    /** The state for {@code obs} and the goal of the throw about to be made. */
    public static double[] encode(Observation obs, double[] goal) {
        double[] s = new double[BASE_SIZE + goal.length];
        Frame palm = obs.palm();
        put(s, 0, palm.origin());
        put(s, 3, palm.rotation().toRotationVector());
        put(s, 6, palm.rotation().inverseRotate(obs.object().position().minus(palm.origin())));
        put(s, 9, obs.object().orientation().toRotationVector());
        System.arraycopy(goal, 0, s, BASE_SIZE, goal.length);
        return s;
    }

    private static void put(double[] s, int at, Vec3 v) {
        s[at] = v.x();
        s[at + 1] = v.y();
        s[at + 2] = v.z();
    }
}
