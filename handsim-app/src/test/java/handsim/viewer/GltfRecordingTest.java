package handsim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import handsim.AppTestSupport;
import handsim.TestSupport;
import handsim.scene.LiveRun;
import handsim.scene.SimClock;
import handsim.sim.ode.OdeSimulator;
import handsim.scene.CatchLoopScene;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The viewer's G key: pressed, the frames the viewer draws are sampled; pressed again, they are
 * written as one .glb beside the PNG recordings, with the floor, the goal plane and the camera.
 * The run is advanced by hand at 60 Hz, as in {@link ViewerTest}.
 */
@Tag("slow")
class GltfRecordingTest {

    static final double FRAME = 1 / 60.0;
    static final int FRAMES = 30;

    @Test
    void gStartsAndStopsAGlbOfTheFramesDrawn(@TempDir Path dir) throws Exception {
        ViewerConfig config = AppTestSupport.viewerConfig();
        CatchLoopScene scene = AppTestSupport.heightLoopScene(new OdeSimulator(TestSupport.model(), TestSupport.simConfig()), "sphere", 1);
        ViewerConfig.Pacing p = config.pacing();
        List<String> notes = new ArrayList<>();
        try (LiveRun run = new LiveRun(scene, new SimClock(p.maxLagSeconds()), p.minChunkSeconds(), p.maxChunkSeconds(), notes::add);
                Viewer viewer = new Viewer(config, run, dir, "handsim test", false)) {
            viewer.controls().perform(ViewerAction.RECORD_GLTF);
            for (int f = 0; f < FRAMES; f++) {
                run.update(FRAME);
                while (run.update(0)) {
                    // the run's thread would catch up like this
                }
                viewer.run(1);
            }
            viewer.controls().perform(ViewerAction.RECORD_GLTF);
            viewer.run(1);
        }
        List<Path> written;
        try (Stream<Path> s = Files.list(dir)) {
            written = s.filter(f -> f.getFileName().toString().endsWith(".glb")).toList();
        }
        assertEquals(1, written.size(), "one recording: " + notes);
        JsonNode json = jsonChunk(Files.readAllBytes(written.get(0)));
        // a frame drawn every 1/60 s of simulated time, sampled at gltfRate = 60 Hz: one sample per frame
        // drawn while recording (the first on the frame that started it)
        int keyframes = json.get("accessors").get(json.get("animations").get(0).get("samplers").get(0).get("input").asInt())
                .get("count").asInt();
        assertEquals(60, config.recording().gltfRate(), 1e-12);
        assertTrue(Math.abs(keyframes - FRAMES) <= 1, "keyframes " + keyframes + " for " + FRAMES + " frames");
        List<String> names = new ArrayList<>();
        json.get("nodes").forEach(n -> names.add(n.path("name").asText()));
        assertTrue(names.containsAll(List.of("palm", "sphere", "floor", "goal plane", "camera")), names.toString());
        assertTrue(notes.stream().anyMatch(n -> n.startsWith("recorded " + keyframes + " glTF samples")), notes.toString());
    }

    private static JsonNode jsonChunk(byte[] glb) throws Exception {
        ByteBuffer b = ByteBuffer.wrap(glb).order(ByteOrder.LITTLE_ENDIAN);
        assertEquals(0x46546C67, b.getInt(0), "glTF magic");
        return new ObjectMapper().readTree(new String(glb, 20, b.getInt(12), StandardCharsets.UTF_8));
    }
}
