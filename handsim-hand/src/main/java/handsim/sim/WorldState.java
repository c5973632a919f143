package handsim.sim;

import java.util.List;
import java.util.Optional;

/**
 * Everything a {@link Simulator} needs to go on from one instant: every body's state, the joint
 * torques being applied, the object, the static boxes, the clock and the engine's random
 * generator. A world restored from it ({@link Simulator#restoreState}) steps on exactly as the
 * one it was captured from, so a planner can try a move in a twin world before the real one
 * makes it. Immutable: the arrays are copied in and handed out as copies.
 *
 * @param bodies per model body, 13 numbers: centre of mass (3), orientation w, x, y, z (4),
 *     linear velocity (3), angular velocity (3), world frame
 * @param torques joint torques (N m) in the model's DOF order
 * @param object the object's spec and state, if one is in the world
 * @param randomSeed the engine's random generator (quickStep shuffles its rows with it)
 */
public record WorldState(double time, long steps, double[] bodies, double[] torques, Optional<ObjectSpec> objectSpec,
        Optional<RigidState> object, List<WorldSnapshot.StaticBox> boxes, long randomSeed) {

    /** Numbers per body in {@link #bodies}. */
    public static final int PER_BODY = 13;

    public WorldState {
        bodies = bodies.clone();
        torques = torques.clone();
        boxes = List.copyOf(boxes);
        if (objectSpec.isPresent() != object.isPresent()) {
            throw new IllegalArgumentException("an object needs both its spec and its state");
        }
    }

    @Override
    public double[] bodies() {
        return bodies.clone();
    }

    @Override
    public double[] torques() {
        return torques.clone();
    }
}
