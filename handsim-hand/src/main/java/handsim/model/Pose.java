package handsim.model;

import java.util.Arrays;

/**
 * A named set of joint angles (radians) for some of the model's DOFs, e.g. the neutral, open
 * and closed hand poses.
 *
 * @param dofs model DOF indices, ascending
 * @param angles target angle of each listed DOF
 */
public record Pose(String name, int[] dofs, double[] angles) {

    public Pose {
        if (dofs.length != angles.length) {
            throw new IllegalArgumentException("pose " + name + ": " + dofs.length + " dofs but " + angles.length + " angles");
        }
        dofs = dofs.clone();
        angles = angles.clone();
    }

    /** Angle of model DOF {@code dof}, or {@code fallback} when the pose does not set it. */
    public double angle(int dof, double fallback) {
        int i = Arrays.binarySearch(dofs, dof);
        return i >= 0 ? angles[i] : fallback;
    }

    public boolean sets(int dof) {
        return Arrays.binarySearch(dofs, dof) >= 0;
    }

    /** Writes the pose's angles into a full DOF vector, leaving the other entries alone. */
    public void applyTo(double[] q) {
        for (int i = 0; i < dofs.length; i++) {
            q[dofs[i]] = angles[i];
        }
    }
}
