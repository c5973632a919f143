package handsim.export;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import handsim.AppTestSupport;
import handsim.TestSupport;
import handsim.viewer.Camera;
import handsim.viewer.ExportLook;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The Khronos glTF Validator (npm gltf-validator, run by {@code scripts/gltf-viewer/validate.mjs})
 * finds no error and no warning in an export with everything in it: the arm, the hand, an object
 * of two sizes over a reset, the floor, the goal plane and the camera, as .glb and as .gltf + .bin.
 */
@Tag("browser")
@Tag("slow")
class GltfValidatorTest {

    @Test
    void theValidatorFindsNoErrorAndNoWarning(@TempDir Path dir) throws Exception {
        WebTools.requireNode();
        RecordedRun run = new RecordedRun("can", 3, 1.5, 60, 0.8);
        var options = ExportLook.options(AppTestSupport.viewerConfig(), true, true, Optional.of(new Camera(AppTestSupport.viewerConfig().camera())));
        for (String name : List.of("run.glb", "run.gltf")) {
            Path file = dir.resolve(name);
            ExportTarget.of(file, null, "--out", "--format").write(run.clip, options);
            String printed = WebTools.run(WebTools.VIEWER, List.of("node", "validate.mjs", file.toString()));
            JsonNode report = new ObjectMapper().readTree(printed);
            assertEquals(0, report.get("numErrors").asInt(), name + ": " + report.get("messages"));
            assertEquals(0, report.get("numWarnings").asInt(), name + ": " + report.get("messages"));
            assertEquals(1, report.get("info").get("animationCount").asInt(), name);
        }
    }
}
