package handsim.model;

import handsim.math.Vec3;

/**
 * A joint between a parent body (or the fixed world, {@code parent == -1}) and a child body.
 *
 * @param anchor joint centre in world coordinates in the zero configuration; it is also the
 *     origin of the child body's frame
 * @param firstDof index of the joint's first DOF in the model's DOF vector
 */
public record Joint(int index, String name, JointType type, int parent, int child, Vec3 anchor, int firstDof) {

    public int dofCount() {
        return type.dofCount();
    }

    public boolean isRoot() {
        return parent < 0;
    }
}
