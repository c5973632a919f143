package handsim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.AppTestSupport;
import handsim.TestSupport;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.ControllerConfig;
import handsim.evaluation.CatchEvaluation;
import handsim.kin.Frame;
import handsim.math.Vec3;
import handsim.scene.CatchLoopScene;
import handsim.scene.HeightControl;
import handsim.scene.LiveFrame;
import handsim.scene.LiveRun;
import handsim.scene.SimClock;
import handsim.sim.ode.OdeSimulator;
import handsim.task.EpisodeLimits;
import handsim.task.Goal;
import handsim.task.HeightGoals;
import handsim.task.LaunchDistribution;
import handsim.taskdef.SteeredTask;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The viewer's window, under an X display (xvfb-run in the project's test command): a fixed
 * number of frames of seed 1 with the run advanced by hand at 60 Hz (so the frame drawn is the
 * same every time), a screenshot, and the arm, the object and the goal plane found where the
 * camera projects them.
 */
@Tag("fast")
class ViewerTest {

    static final long SEED = 1;
    static final double FRAME = 1 / 60.0;
    /** 0.6 s simulated: the thrown-in sphere falls toward the hand, 0.35 m above it, in view. */
    static final int FRAMES = 36;
    /** Per-channel tolerance on a shaded colour (light and shading change it, the hue stays). */
    static final int COLOUR_TOLERANCE = 90;
    /** The translucent red goal plane over the light background: red clearly above green and blue. */
    static final int PLANE_RED_MARGIN = 25;

    @Test
    void drawsTheArmTheObjectAndTheGoalPlaneWhereTheCameraProjectsThem(@TempDir Path dir) throws Exception {
        ViewerConfig config = AppTestSupport.viewerConfig();
        ControllerConfig cc = ControllerConfig.load(Home.resolve("configs/controller.json"));
        SteeredTask steered = TestSupport.configs().height().steered("sphere", HeightGoals.fixed(1.2), 0.8, 1.7);
        CatchEvaluation evaluation = CatchEvaluation.nominal(cc, EpisodeLimits.parse(Json.load(Home.resolve("configs/episode.json"))),
                LaunchDistribution.load(Home.resolve("configs/launch.json")), TestSupport.object("sphere"), steered.task());
        CatchLoopScene scene = new CatchLoopScene(new OdeSimulator(TestSupport.model(), TestSupport.simConfig()), evaluation, steered, SEED,
                new HeightControl(0.05, 0.8, 1.7), null);
        ViewerConfig.Pacing p = config.pacing();
        try (LiveRun run = new LiveRun(scene, new SimClock(p.maxLagSeconds()), p.minChunkSeconds(), p.maxChunkSeconds(), s -> { });
                Viewer viewer = new Viewer(config, run, dir, "handsim test", false)) {
            for (int f = 0; f < FRAMES; f++) {
                run.update(FRAME);
                while (run.update(0)) {
                    // the run's thread would catch up like this
                }
                assertEquals(1, viewer.run(1).frames());
            }
            LiveFrame drawn = viewer.lastDrawn();
            assertNotNull(drawn);
            assertEquals(FRAMES * FRAME, drawn.snapshot().time(), p.minChunkSeconds() + 0.002, "paced by the frames' 60 Hz");
            Path file = viewer.writeScreenshot(dir.resolve("shot.png"));
            BufferedImage img = ImageIO.read(file.toFile());
            int[] size = viewer.size();
            assertEquals(size[0], img.getWidth());
            assertEquals(size[1], img.getHeight());

            Set<Integer> colours = new HashSet<>();
            for (int y = 0; y < img.getHeight(); y += 3) {
                for (int x = 0; x < img.getWidth(); x += 3) {
                    colours.add(img.getRGB(x, y) & 0xffffff);
                }
            }
            assertTrue(colours.size() > 50, "shaded scene, not a blank frame: " + colours.size() + " colours");

            Camera camera = viewer.camera();
            var snap = drawn.snapshot();
            Vec3 ball = snap.object().orElseThrow().position();
            assertColour(img, camera.project(ball, size[0], size[1]), config.colours().object(), "object");

            Frame upperArm = snap.bodies().get(0);
            Vec3 armPoint = upperArm.pointToWorld(snap.model().bodies().get(0).shapes().get(0).centroid());
            assertColour(img, camera.project(armPoint, size[0], size[1]), config.colours().skin(), "upper arm");

            Goal.Height goal = (Goal.Height) drawn.goal();
            // a point of the plane on the side away from the heads-up panels
            Vec3 planePoint = new Vec3(goal.center().x(), goal.height(), goal.center().z() + 0.6 * config.goals().planeHalfSize());
            double[] px = camera.project(planePoint, size[0], size[1]);
            int rgb = pixel(img, px);
            int r = rgb >> 16 & 0xff, g = rgb >> 8 & 0xff, b = rgb & 0xff;
            assertTrue(r > g + PLANE_RED_MARGIN && r > b + PLANE_RED_MARGIN,
                    String.format("goal plane at (%.0f, %.0f): rgb(%d, %d, %d)", px[0], px[1], r, g, b));
        }
    }

    private static int pixel(BufferedImage img, double[] px) {
        assertNotNull(px, "in front of the camera");
        int x = (int) Math.round(px[0]), y = (int) Math.round(px[1]);
        assertTrue(x >= 0 && y >= 0 && x < img.getWidth() && y < img.getHeight(), "inside the image: " + x + ", " + y);
        return img.getRGB(x, y);
    }

    private static void assertColour(BufferedImage img, double[] px, float[] want, String what) {
        int rgb = pixel(img, px);
        int r = rgb >> 16 & 0xff, g = rgb >> 8 & 0xff, b = rgb & 0xff;
        assertTrue(Math.abs(r - 255 * want[0]) < COLOUR_TOLERANCE && Math.abs(g - 255 * want[1]) < COLOUR_TOLERANCE
                && Math.abs(b - 255 * want[2]) < COLOUR_TOLERANCE && r > g && g > b,
                String.format("%s colour at its projected centre (%.0f, %.0f), got rgb(%d, %d, %d)", what, px[0], px[1], r, g, b));
    }
}
