package handsim.export;

import handsim.kin.Kinematics;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.model.Joint;
import java.util.ArrayList;
import java.util.List;

/**
 * A joint's three BVH rotation channels, in the model's Euler order: the coordinate axis of each
 * DOF in turn (the one its axis lies along), then the axes no DOF uses (always 0 for such a
 * joint). A DOF whose axis is {@code -x} turns the x channel by minus its angle. The thumb's axes
 * lie obliquely: its channels are then the joint's rotation split into Euler angles about the
 * axes nearest its DOFs' (in their order), the same rotation, but not one angle per channel.
 */
final class BvhChannels {

    static final String[] NAMES = {"Xrotation", "Yrotation", "Zrotation"};
    /** An axis counts as a coordinate axis when its component along it is this close to 1. */
    static final double ALIGNED = 1e-9;

    private final Joint joint;
    private final Kinematics kinematics;
    /** The coordinate axis of each channel. */
    final int[] order;
    /** Per DOF of an aligned joint: +1 or -1 (the axis along or against its coordinate axis); null for an oblique joint. */
    private final double[] signs;

    BvhChannels(HandModel model, Kinematics kinematics, Joint joint) {
        this.joint = joint;
        this.kinematics = kinematics;
        List<Integer> axes = new ArrayList<>();
        double[] s = new double[joint.dofCount()];
        boolean aligned = true;
        for (int d = 0; d < joint.dofCount(); d++) {
            Vec3 axis = model.dofs().get(joint.firstDof() + d).axis();
            int nearest = -1;
            for (int k = 0; k < 3; k++) {
                if (!axes.contains(k) && (nearest < 0 || Math.abs(axis.get(k)) > Math.abs(axis.get(nearest)))) {
                    nearest = k;
                }
            }
            axes.add(nearest);
            s[d] = Math.signum(axis.get(nearest));
            aligned &= Math.abs(Math.abs(axis.get(nearest)) - 1) < ALIGNED;
        }
        for (int k = 0; k < 3; k++) {
            if (!axes.contains(k)) {
                axes.add(k);
            }
        }
        order = axes.stream().mapToInt(Integer::intValue).toArray();
        signs = aligned ? s : null;
    }

    /** Whether every DOF turns about a coordinate axis (then a channel is a DOF's angle, signed). */
    boolean aligned() {
        return signs != null;
    }

    /** The channels' values (rad) for the joint's relative rotation (child frame in parent frame). */
    double[] values(Quat relative) {
        double[] q = new double[kinematics.model().dofCount()];
        // the simulator's own reading of the joint's angles (Simulator.readJoints)
        kinematics.decompose(joint, relative, q);
        if (signs == null) {
            return Euler.decompose(kinematics.jointRotation(joint, q), order);
        }
        double[] v = new double[3];
        for (int d = 0; d < joint.dofCount(); d++) {
            v[d] = signs[d] * q[joint.firstDof() + d];
        }
        return v;
    }
}
