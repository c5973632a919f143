package handsim.sim;

import handsim.kin.Frame;
import handsim.math.Vec3;
import handsim.model.HandModel;
import java.util.List;
import java.util.Optional;

/**
 * An immutable picture of the world at one instant, for drawing: the viewer and the PNG
 * renderer read snapshots and never touch the simulation.
 *
 * @param bodies world frame of every model body, in model order
 * @param object the thrown object's spec and state, if one is in the world
 * @param boxes static boxes (centre, size)
 */
public record WorldSnapshot(HandModel model, double time, List<Frame> bodies, Optional<ObjectSpec> objectSpec,
        Optional<RigidState> object, List<StaticBox> boxes, double groundHeight) {

    /** A fixed box in the scene. */
    public record StaticBox(Vec3 center, Vec3 size) {
    }

    public WorldSnapshot {
        bodies = List.copyOf(bodies);
        boxes = List.copyOf(boxes);
    }
}
