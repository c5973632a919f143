package handsim.viewer;

import handsim.export.ExportOptions;
import java.util.Optional;

/** The viewer's look for an animation export: its colours, floor and goal plane ({@code configs/viewer.json}) and its camera. */
public final class ExportLook {

    private ExportLook() {
    }

    /** The extras and colours of {@code config}, with the floor, the goal and the camera as given. */
    public static ExportOptions options(ViewerConfig config, boolean floor, boolean goal, Optional<Camera> camera) {
        ViewerConfig.Palette c = config.colours();
        return new ExportOptions(floor, goal, camera.map(ExportLook::view),
                new ExportOptions.Colours(c.skin(), c.palm(), c.object(), c.staticBox(), c.goalPlane(), c.goalBox(), c.floorLight(),
                        c.floorDark()),
                config.stage().floorHalfSize(), config.stage().floorTile(), config.goals().planeHalfSize(), config.stage().roughness());
    }

    /** Where {@code camera} stands and looks now, with its field of view and clipping planes. */
    public static ExportOptions.CameraView view(Camera camera) {
        return new ExportOptions.CameraView(camera.eye(), camera.target, camera.fovY, Camera.NEAR, Camera.FAR);
    }
}
