package handsim.export;

import handsim.math.Vec3;
import java.util.Optional;

/**
 * What a glTF export holds besides the arm, the hand and the object (always there), and how it
 * looks: the viewer's colours ({@code configs/viewer.json}), RGBA in [0, 1] as the viewer draws
 * them (sRGB).
 *
 * @param floor the checkered floor (square of side 2 {@code floorHalfSize}, tiles of {@code floorTile}, m)
 * @param goal the task's goal: the height plane (square of side 2 {@code goalPlaneHalfSize}, m) or the box
 * @param camera a camera node, or empty
 * @param roughness the surface finish of every material (glTF's metallic-roughness model, in [0, 1])
 */
public record ExportOptions(boolean floor, boolean goal, Optional<CameraView> camera, Colours colours, double floorHalfSize,
        double floorTile, double goalPlaneHalfSize, double roughness) {

    /** The viewer's colours of what the export can hold. */
    public record Colours(float[] skin, float[] palm, float[] object, float[] staticBox, float[] goalPlane, float[] goalBox,
            float[] floorLight, float[] floorDark) {
    }

    /**
     * A perspective camera at {@code eye} looking at {@code target} with the world's y up, of
     * vertical field of view {@code fovY} (rad), between the {@code near} and {@code far} planes (m).
     */
    public record CameraView(Vec3 eye, Vec3 target, double fovY, double near, double far) {
    }
}
