package handsim.viewer;

import handsim.kin.Frame;
import handsim.kin.Kinematics;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.model.Joint;
import java.util.ArrayList;
import java.util.List;

/**
 * The world rotation axis of every DOF, recovered from a snapshot's body frames alone: each
 * joint's relative rotation is decomposed into its Euler angles and the axes rebuilt along the
 * chain ({@link Kinematics#decompose}, {@link Kinematics#worldAxes}). No OpenGL.
 */
final class JointAxes {

    /** The axis of DOF {@code slot} (0 nearest the parent) of a joint, from its anchor (world). */
    record Axis(Vec3 anchor, Vec3 direction, int slot) {
    }

    private final HandModel model;
    private final Kinematics kin;
    private final double[] q;

    JointAxes(HandModel model) {
        this.model = model;
        this.kin = new Kinematics(model);
        this.q = new double[model.dofCount()];
    }

    HandModel model() {
        return model;
    }

    List<Axis> compute(handsim.sim.WorldSnapshot s) {
        List<Axis> out = new ArrayList<>(model.dofCount());
        List<Frame> frames = s.bodies();
        for (Joint j : model.joints()) {
            Quat parent = j.isRoot() ? Quat.IDENTITY : frames.get(j.parent()).rotation();
            Frame child = frames.get(j.child());
            kin.decompose(j, parent.conjugate().mul(child.rotation()), q);
            Vec3[] w = kin.worldAxes(j, parent, q);
            for (int slot = 0; slot < w.length; slot++) {
                out.add(new Axis(child.origin(), w[slot], slot));
            }
        }
        return out;
    }
}
