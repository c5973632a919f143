package handsim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.AppTestSupport;
import handsim.TestSupport;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.sim.Simulator;
import handsim.sim.WorldSnapshot;
import handsim.sim.ode.OdeSimulator;
import handsim.task.HeldBallScenario;
import handsim.scene.HeldBallScene;
import handsim.task.ServoLoop;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Off-screen rendering of the held-ball scene. Needs an X display: the project's test command
 * (scripts/handsim test, .ci/run) provides one with xvfb-run; without one this test fails with
 * the renderer's message rather than passing silently.
 */
@Tag("fast")
class RenderSmokeTest {

    static final int WIDTH = 480, HEIGHT = 360;
    /** Per-channel tolerance on the object's colour: shading darkens or lightens it, the hue stays orange. */
    static final int COLOUR_TOLERANCE = 90;

    @Test
    void writesANonBlankFrameWithTheBallWhereTheCameraProjectsIt(@TempDir Path dir) throws Exception {
        HandModel model = TestSupport.model();
        Simulator sim = new OdeSimulator(model, TestSupport.simConfig());
        try (HeldBallScene scene = new HeldBallScene(new HeldBallScenario(new ServoLoop(sim, TestSupport.pd(model)),
                TestSupport.object("sphere"), 0.2, 1));
                OffscreenRenderer renderer = new OffscreenRenderer(WIDTH, HEIGHT, AppTestSupport.viewerConfig())) {
            scene.advance(0.15); // the ball in flight, above the hand: nothing hides it
            WorldSnapshot snap = scene.snapshot();
            Camera camera = new Camera(AppTestSupport.viewerConfig().camera());
            Path file = dir.resolve("00000.png");
            FrameFolder.writePng(renderer.render(snap, camera, null), file);

            assertTrue(Files.size(file) > 1000, "a PNG was written");
            BufferedImage img = ImageIO.read(file.toFile());
            assertEquals(WIDTH, img.getWidth());
            assertEquals(HEIGHT, img.getHeight());
            Set<Integer> colours = new HashSet<>();
            for (int y = 0; y < HEIGHT; y += 2) {
                for (int x = 0; x < WIDTH; x += 2) {
                    colours.add(img.getRGB(x, y) & 0xffffff);
                }
            }
            assertTrue(colours.size() > 50, "shaded scene, not a blank frame: " + colours.size() + " colours");

            Vec3 ball = snap.object().orElseThrow().position();
            double[] px = camera.project(ball, WIDTH, HEIGHT);
            int rgb = img.getRGB((int) Math.round(px[0]), (int) Math.round(px[1]));
            int r = rgb >> 16 & 0xff, g = rgb >> 8 & 0xff, b = rgb & 0xff;
            float[] want = AppTestSupport.viewerConfig().colours().object();
            assertTrue(Math.abs(r - 255 * want[0]) < COLOUR_TOLERANCE && Math.abs(g - 255 * want[1]) < COLOUR_TOLERANCE
                    && Math.abs(b - 255 * want[2]) < COLOUR_TOLERANCE && r > g && g > b,
                    String.format("object colour at its projected centre (%.0f, %.0f), got rgb(%d, %d, %d)", px[0], px[1], r, g, b));
        }
    }
}
