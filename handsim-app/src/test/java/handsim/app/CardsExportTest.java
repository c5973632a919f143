package handsim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import handsim.cards.sim.Trajectory;
import handsim.export.WebTools;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A reduced Double Lift trial (four card-stock cards, coarse fingertips, 0.4 s) leaves the
 * program: {@code export --scene double-lift} writes it as .glb and as .gltf + .bin, the Khronos
 * glTF Validator finds no error and no warning in either and sees the morph-target animation,
 * three.js draws the lift (its first and last frames differ where the cards rose), and the
 * viewer plays the same trajectory.
 */
@Tag("browser")
@Tag("slow")
class CardsExportTest {

    static final int WIDTH = 480, HEIGHT = 360;

    @Test
    void aCardTrialExportsAsValidGltfThatThreeJsPlays(@TempDir Path dir) throws Exception {
        WebTools.requireChromium();
        Path trial = dir.resolve("lift");
        assertEquals(0, Main.run("cards", "lift", "--mesh", "coarse", "--card", "cardStock", "--no-frames", "--out", trial.toString(),
                "--set", "double-lift.stack.count=4", "--set", "double-lift.trial.duration=0.4", "--set", "double-lift.trial.restAfterLift=0.05",
                "--set", "double-lift.params={\"hStart\": 0, \"t0\": 0, \"t1\": 0.08, \"vp\": 0.006, \"t2\": 0.1, \"t3\": 0.3, \"vs\": 0.025}"));
        Path trajectory = trial.resolve("trajectory.json");
        int frames = Trajectory.read(trajectory).frames().size();
        for (String name : List.of("lift.glb", "lift.gltf")) {
            Path file = dir.resolve(name);
            assertEquals(0, Main.run("export", "--scene", "double-lift", "--trajectory", trajectory.toString(), "--out", file.toString()));
            JsonNode report = new ObjectMapper().readTree(WebTools.run(WebTools.VIEWER, List.of("node", "validate.mjs", file.toString())));
            assertEquals(0, report.get("numErrors").asInt(), name + ": " + report.get("messages"));
            assertEquals(0, report.get("numWarnings").asInt(), name + ": " + report.get("messages"));
            assertEquals(1, report.get("info").get("animationCount").asInt(), name);
            assertTrue(report.get("info").get("hasMorphTargets").asBoolean(), name + ": the surfaces move by morph targets");
        }
        // three.js through the file's camera: the first and the last frame differ where the top cards rose
        Path glb = dir.resolve("lift.glb");
        double end = 0.4 - 1e-3;
        BufferedImage first = ImageIO.read(WebTools.screenshot("src=" + glb.toUri() + "&t=0", WIDTH, HEIGHT, dir.resolve("first.png")).toFile());
        BufferedImage last = ImageIO.read(WebTools.screenshot("src=" + glb.toUri() + "&t=" + end, WIDTH, HEIGHT, dir.resolve("last.png")).toFile());
        int changed = 0;
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                int a = first.getRGB(x, y), b = last.getRGB(x, y);
                int d = Math.abs((a >> 16 & 0xff) - (b >> 16 & 0xff)) + Math.abs((a >> 8 & 0xff) - (b >> 8 & 0xff)) + Math.abs((a & 0xff) - (b & 0xff));
                changed += d > 60 ? 1 : 0;
            }
        }
        // the fingertips rise 5 mm and the top cards about 3 mm: some thousand pixels at this framing (a few hundred would be noise)
        assertTrue(changed > 1000, "pixels that changed between the first and the last frame: " + changed + " (" + frames + " frames)");
        assertEquals(0, Main.run("view", "--scene", "double-lift", "--trajectory", trajectory.toString(), "--benchmark-frames", "2"));
    }
}
