package handsim.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.AppTestSupport;
import handsim.TestSupport;
import handsim.kin.Frame;
import handsim.model.Body;
import handsim.model.HandModel;
import handsim.viewer.Camera;
import handsim.viewer.ExportLook;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import handsim.model.Shape;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The exported glTF, read back by a reader of its own ({@link GltfReader}), reproduces the
 * simulated world transforms of every body and of the object at every sample, and its node tree
 * is the model's body tree at the model's rest offsets.
 */
@Tag("slow")
class GltfRoundTripTest {

    /**
     * 1e-6 m and 1e-6 rad (the bound). glTF holds single-precision floats: each local
     * translation and rotation is within about 6e-8 of the double; composed down the seven levels
     * from the shoulder to a fingertip that stays below 1e-6.
     */
    static final double METRES = 1e-6, RADIANS = 1e-6;

    static RecordedRun run;
    @TempDir
    static Path dir;

    @BeforeAll
    static void record() {
        // the can: cylinder caps, and an object that turns in flight; 2 s hold the throw-in's catch; a new
        // throw at 1.2 s resets the world (the recording's clock goes on) with a can of another size
        run = new RecordedRun("can", 3, 2.0, 60, 1.2);
    }

    @Test
    void aGlbReadBackGivesTheSimulatedTransformsAtEverySample() throws Exception {
        assertRoundTrip(write("run.glb"));
    }

    @Test
    void aGltfWithItsBinReadBackGivesTheSameTransforms() throws Exception {
        Path file = write("run.gltf");
        assertTrue(Files.isRegularFile(dir.resolve("run.bin")), "the buffer beside the .gltf");
        assertRoundTrip(file);
    }

    @Test
    void theNodeTreeIsTheModelsBodyTreeAtItsRestOffsets() throws Exception {
        GltfReader gltf = GltfReader.read(write("tree.glb"));
        HandModel model = run.clip.model();
        int group = gltf.node(model.name());
        for (Body b : model.bodies()) {
            int n = gltf.node(b.name());
            assertEquals(b.parent() < 0 ? group : gltf.node(model.bodies().get(b.parent()).name()), gltf.parent(n), b.name() + "'s parent");
            var t = gltf.json.get("nodes").get(n).get("translation");
            var rest = b.origin().minus(b.parent() < 0 ? handsim.math.Vec3.ZERO : model.bodies().get(b.parent()).origin());
            for (int k = 0; k < 3; k++) {
                assertEquals(rest.get(k), t.get(k).asDouble(), 1e-7, b.name() + "'s rest offset from its parent (the model's zero configuration)");
            }
            assertTrue(gltf.json.get("nodes").get(n).has("mesh"), b.name() + " has the mesh of its shapes");
        }
        assertEquals(-1, gltf.parent(gltf.node("can")), "the object is a node of its own");
    }

    @Test
    void eachSizeOfTheObjectIsShownWhileItIsInTheWorld() throws Exception {
        GltfReader gltf = GltfReader.read(write("sizes.glb"));
        List<List<Shape>> sizes = run.clip.samples().stream().map(s -> s.objectSpec().shapes()).distinct().toList();
        assertEquals(2, sizes.size(), "the new throw's can has another size");
        for (int k = 0; k < sizes.size(); k++) {
            int child = gltf.node("can " + (k + 1));
            assertEquals(gltf.node("can"), gltf.parent(child));
            float[] scale = gltf.floats(gltf.output(child, "scale"));
            for (int i = 0; i < run.clip.samples().size(); i++) {
                boolean shown = run.clip.samples().get(i).objectSpec().shapes().equals(sizes.get(k));
                assertEquals(shown ? 1f : 0f, scale[3 * i], "size " + (k + 1) + " at sample " + i);
            }
        }
        // the sample times go on over the reset, one sample every 1/60 s
        float[] times = gltf.times(gltf.node("can"), "translation");
        for (int i = 1; i < times.length; i++) {
            assertEquals(1 / 60.0, times[i] - times[i - 1], 0.0021, "samples within a 2 ms tick of the 60 Hz grid");
        }
    }

    @Test
    void everyLitMaterialHasTheViewersRoughness() throws Exception {
        // configs/viewer.json scene.roughness: the surface finish of every material but the unlit goal's
        GltfReader gltf = GltfReader.read(write("materials.glb"));
        int lit = 0;
        for (com.fasterxml.jackson.databind.JsonNode m : gltf.json.get("materials")) {
            if (!m.has("extensions")) {
                assertEquals(AppTestSupport.viewerConfig().stage().roughness(), m.get("pbrMetallicRoughness").get("roughnessFactor").asDouble(),
                        0, m.toString());
                lit++;
            }
        }
        assertTrue(lit >= 3, "skin, palm and object at least: " + gltf.json.get("materials"));
        assertEquals(0.6, AppTestSupport.viewerConfig().stage().roughness(), 0, "the shipped finish");
    }

    private static Path write(String name) throws Exception {
        Path file = dir.resolve(name);
        ExportTarget.of(file, null, "--out", "--format").write(run.clip,
                ExportLook.options(AppTestSupport.viewerConfig(), true, true, Optional.of(new Camera(AppTestSupport.viewerConfig().camera()))));
        return file;
    }

    private static void assertRoundTrip(Path file) throws Exception {
        GltfReader gltf = GltfReader.read(file);
        HandModel model = run.clip.model();
        int object = gltf.node("can");
        double worstMetres = 0, worstRadians = 0;
        for (Body b : model.bodies()) {
            int n = gltf.node(b.name());
            float[] times = gltf.times(n, "rotation");
            assertEquals(run.clip.samples().size(), times.length, "a keyframe per sample");
            for (int i = 0; i < times.length; i++) {
                MotionClip.Sample s = run.clip.samples().get(i);
                assertEquals(s.time(), times[i], 1e-6, "keyframe " + i + " at the sample's time");
                Frame want = s.body(b.index()), got = gltf.world(n, i);
                worstMetres = Math.max(worstMetres, want.origin().distance(got.origin()));
                worstRadians = Math.max(worstRadians, want.rotation().angleTo(got.rotation()));
            }
        }
        for (int i = 0; i < run.clip.samples().size(); i++) {
            Frame want = run.clip.samples().get(i).objectFrame(), got = gltf.world(object, i);
            worstMetres = Math.max(worstMetres, want.origin().distance(got.origin()));
            worstRadians = Math.max(worstRadians, want.rotation().angleTo(got.rotation()));
        }
        System.out.printf("%s: largest position error %.2e m, rotation error %.2e rad over %d samples%n", file.getFileName(),
                worstMetres, worstRadians, run.clip.samples().size());
        assertTrue(worstMetres <= METRES, "largest position error " + worstMetres + " m");
        assertTrue(worstRadians <= RADIANS, "largest rotation error " + worstRadians + " rad");
        // and the motion is no still life: the can was thrown in and caught
        Frame first = run.clip.samples().get(0).objectFrame(), last = run.clip.samples().get(run.clip.samples().size() - 1).objectFrame();
        assertTrue(first.origin().distance(last.origin()) > 0.1, "the object moved");
    }
}
