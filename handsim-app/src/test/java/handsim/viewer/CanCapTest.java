package handsim.viewer;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.AppTestSupport;
import handsim.TestSupport;
import handsim.kin.Frame;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.sim.ObjectSpec;
import handsim.sim.RigidState;
import handsim.sim.WorldSnapshot;
import java.awt.image.BufferedImage;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * A can seen end-on shows its cap, lit. The camera looks along the can's axis from the side the
 * light comes from, so the near cap faces the light: drawn, it is lit by the ambient and the full
 * diffuse light; were it culled (wound the wrong way round), the far cap or the tube's inside
 * would show, facing away from the light and lit by the ambient alone.
 */
@Tag("fast")
class CanCapTest {

    static final int SIZE = 240;

    @Test
    void aCanSeenEndOnShowsItsLitCap() {
        ViewerConfig config = AppTestSupport.viewerConfig();
        HandModel model = TestSupport.model();
        ObjectSpec can = TestSupport.object("can");
        Vec3 centre = new Vec3(0, 1.0, 0);
        Vec3 towardLight = config.stage().light().negate().normalized();
        // the can's long axis (object y) along the line of sight
        Quat orientation = Quat.between(Vec3.Y, towardLight);
        // the arm far beyond the far plane: only the can, the floor and shadows are in view
        List<Frame> away = Collections.nCopies(model.bodyCount(), new Frame(new Vec3(1000, 0, 1000), Quat.IDENTITY));
        WorldSnapshot snapshot = new WorldSnapshot(model, 0, away, Optional.of(can),
                Optional.of(new RigidState(centre, orientation, Vec3.ZERO, Vec3.ZERO)), List.of(), 0);
        Camera camera = new Camera(config.camera());
        camera.target = centre;
        camera.distance = 0.4;
        camera.pitch = Math.asin(towardLight.y());
        camera.yaw = Math.atan2(towardLight.x(), towardLight.z());
        try (OffscreenRenderer renderer = new OffscreenRenderer(SIZE, SIZE, config)) {
            BufferedImage img = renderer.render(snapshot, camera, null);
            double[] px = camera.project(centre.plus(towardLight.times(0.05)), SIZE, SIZE);
            assertNotNull(px);
            int rgb = img.getRGB((int) Math.round(px[0]), (int) Math.round(px[1]));
            int red = rgb >> 16 & 0xff;
            float[] object = config.colours().object();
            // fixed-function lighting (SceneRenderer.begin): ambient 0.38, diffuse 0.75 at N.L = 1, so the
            // lit cap's red is min(1, 0.38 + 0.75) x 1.0 = 255 and an unlit surface's 0.38 x 1.0 = 97
            assertTrue(object[0] == 1.0f && red > 200, "the cap's centre is lit: red " + red + " (ambient alone gives ~97)");
            int green = rgb >> 8 & 0xff;
            assertTrue(green < red - 60, "and the object's orange, not the background: rgb " + Integer.toHexString(rgb & 0xffffff));
        }
    }
}
