package handsim.viewer;

import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.AppTestSupport;
import handsim.TestSupport;
import handsim.math.Vec3;
import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Off-screen drawing of deforming surfaces (the card scenes): a square facing the camera lands
 * where the camera projects its centre, in its own colour. Needs an X display, as {@link
 * RenderSmokeTest} does.
 */
@Tag("fast")
class SurfaceRenderTest {

    @Test
    void aSurfaceIsDrawnWhereTheCameraProjectsIt() {
        ViewerConfig config = AppTestSupport.viewerConfig();
        float s = 0.03f;
        // a two-sided square in the plane z = 0 around the origin, red
        SurfaceMesh square = new SurfaceMesh(new float[] {-s, -s, 0, s, -s, 0, s, s, 0, -s, s, 0},
                new int[] {0, 1, 2, 0, 2, 3}, new float[] {0.9f, 0.1f, 0.1f, 1}, true);
        ViewerConfig.CameraHome h = config.camera();
        Camera camera = new Camera(new ViewerConfig.CameraHome(new Vec3(0, 0, 0), 0, 0, 0.2, h.fovY(), 0.06, 1.0,
                h.orbitPerPixel(), h.panPerPixel(), h.zoomPerScroll(), h.followRate()));
        try (OffscreenRenderer renderer = new OffscreenRenderer(160, 120, config)) {
            BufferedImage img = renderer.renderSurfaces(List.of(square), camera);
            double[] px = camera.project(new Vec3(0, 0, 0), 160, 120);
            int rgb = img.getRGB((int) Math.round(px[0]), (int) Math.round(px[1]));
            int r = (rgb >> 16) & 0xff;
            int g = (rgb >> 8) & 0xff;
            int b = rgb & 0xff;
            // lit red: red dominates whatever the shading (tolerance for lighting and ambient)
            assertTrue(r > 80 && r > 2 * g && r > 2 * b, "centre pixel " + Integer.toHexString(rgb));
            int bg = img.getRGB(2, 2);
            assertTrue(((bg >> 16) & 0xff) < 2 * ((bg >> 8) & 0xff), "the corner shows the background, not the square");
        }
    }
}
