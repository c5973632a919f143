package handsim.export;

import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.AppTestSupport;
import handsim.TestSupport;
import handsim.model.HandModel;
import handsim.viewer.Camera;
import handsim.viewer.ExportLook;
import handsim.viewer.ViewerConfig;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Optional;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An independent renderer plays the export: {@code scripts/gltf-viewer/index.html} loads the .glb
 * with three.js in headless Chromium and shows two instants of its animation. In the page's mask
 * mode (flat colours by part) the hand, the object and the rest of the arm are found where the
 * simulation had them: their pixels, centroid and extent, match the parts' meshes posed by the
 * simulated frames and projected by the viewer's camera ({@link PartMasks}).
 */
@Tag("browser")
@Tag("slow")
class GltfViewerBrowserTest {

    static final int WIDTH = 480, HEIGHT = 360;
    /**
     * A few pixels: the two rasterizers differ at the silhouettes' edges only (pixel-centre rules,
     * float against double), so the centroids of parts some hundreds of pixels large agree to well
     * under a pixel; 2 px leaves room for SwiftShader's own rounding.
     */
    static final double CENTROID_PIXELS = 2;
    /** Overlap (intersection over union) of each part's pixels in the two images. */
    static final double MIN_OVERLAP = 0.85;
    /** Parts smaller than this many pixels have too ragged an outline to compare. */
    static final int MIN_PIXELS = 40;

    @Test
    void threeJsDrawsTheHandAndTheObjectWhereTheSimulationHadThem(@TempDir Path dir) throws Exception {
        WebTools.requireChromium();
        ViewerConfig config = AppTestSupport.viewerConfig();
        Camera camera = new Camera(config.camera());
        RecordedRun run = new RecordedRun("sphere", 1, 2.0, 60);
        Path glb = dir.resolve("loop.glb");
        ExportTarget.of(glb, null, "--out", "--format").write(run.clip, ExportLook.options(config, true, true, Optional.of(camera)));
        HandModel model = run.clip.model();

        // two instants a second apart: the sphere falling toward the hand, and after the catch
        int[] samples = {30, 90};
        double[] objectAt = new double[4];
        for (int k = 0; k < samples.length; k++) {
            MotionClip.Sample s = run.clip.samples().get(samples[k]);
            PartMasks want = new PartMasks(s, model, camera, WIDTH, HEIGHT);
            Path png = WebTools.screenshot("src=" + glb.toUri() + "&t=" + s.time() + "&mask=1&hand=palm&object=sphere", WIDTH, HEIGHT,
                    dir.resolve("mask" + k + ".png"));
            BufferedImage got = ImageIO.read(png.toFile());
            for (int part : new int[] {PartMasks.HAND, PartMasks.OBJECT, PartMasks.ARM}) {
                String what = (part == PartMasks.HAND ? "hand" : part == PartMasks.OBJECT ? "object" : "arm") + " at t = " + s.time() + " s";
                assertTrue(want.count(part) >= MIN_PIXELS, what + " in view: " + want.count(part) + " pixels");
                double[] w = centroid(want, part, null), g = centroid(want, part, got);
                double distance = Math.hypot(w[0] - g[0], w[1] - g[1]);
                double overlap = overlap(want, part, got);
                System.out.printf("%s: %d pixels simulated, %d drawn by three.js; centroids %.2f px apart; overlap %.3f%n", what,
                        (int) w[2], (int) g[2], distance, overlap);
                assertTrue(distance <= CENTROID_PIXELS, what + ": centroid " + distance + " px from the simulation's");
                assertTrue(overlap >= MIN_OVERLAP, what + ": overlap " + overlap);
                if (part == PartMasks.OBJECT) {
                    objectAt[2 * k] = g[0];
                    objectAt[2 * k + 1] = g[1];
                }
            }
        }
        assertTrue(Math.hypot(objectAt[2] - objectAt[0], objectAt[3] - objectAt[1]) > 20, "the animation plays: the object moved on screen");

        // the shaded frame: the object in the viewer's orange where it was projected
        MotionClip.Sample s = run.clip.samples().get(samples[0]);
        BufferedImage shaded = ImageIO.read(WebTools.screenshot("src=" + glb.toUri() + "&t=" + s.time(), WIDTH, HEIGHT,
                dir.resolve("shaded.png")).toFile());
        double[] px = camera.project(s.objectFrame().origin(), WIDTH, HEIGHT);
        int rgb = shaded.getRGB((int) px[0], (int) px[1]);
        int r = rgb >> 16 & 0xff, g = rgb >> 8 & 0xff, b = rgb & 0xff;
        assertTrue(r > g + 40 && g > b, String.format("the object's orange (viewer colour 1.0, 0.42, 0.08) at its centre: rgb(%d, %d, %d)", r, g, b));
    }

    /** Which part a screenshot pixel of the mask mode shows: green hand, red object, blue arm. */
    private static int partOf(int rgb) {
        int r = rgb >> 16 & 0xff, g = rgb >> 8 & 0xff, b = rgb & 0xff;
        if (g > 128 && r < 128 && b < 128) {
            return PartMasks.HAND;
        } else if (r > 128 && g < 128 && b < 128) {
            return PartMasks.OBJECT;
        } else if (b > 128 && r < 128 && g < 128) {
            return PartMasks.ARM;
        }
        return PartMasks.NONE;
    }

    /** Centroid (x, y) and pixel count of a part in the reference ({@code image} null) or in the screenshot. */
    private static double[] centroid(PartMasks masks, int part, BufferedImage image) {
        double sx = 0, sy = 0, n = 0;
        for (int y = 0; y < masks.height; y++) {
            for (int x = 0; x < masks.width; x++) {
                int p = image == null ? masks.part[y * masks.width + x] : partOf(image.getRGB(x, y));
                if (p == part) {
                    sx += x + 0.5;
                    sy += y + 0.5;
                    n++;
                }
            }
        }
        return new double[] {sx / n, sy / n, n};
    }

    private static double overlap(PartMasks masks, int part, BufferedImage image) {
        int both = 0, either = 0;
        for (int y = 0; y < masks.height; y++) {
            for (int x = 0; x < masks.width; x++) {
                boolean a = masks.part[y * masks.width + x] == part, b = partOf(image.getRGB(x, y)) == part;
                both += a && b ? 1 : 0;
                either += a || b ? 1 : 0;
            }
        }
        return (double) both / either;
    }
}
