package handsim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code handsim export} end to end: a short run written as .glb, .gltf + .bin and .bvh with
 * nothing else left in the folder; a malformed request refused with one line on stderr and exit
 * status 2, before anything is simulated, leaving no file.
 */
@Tag("slow")
class ExportCommandTest {

    record Result(int code, String out, String err) {
    }

    static Result run(String... args) {
        PrintStream stdout = System.out, stderr = System.err;
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            return new Result(Main.run(args), out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
        } finally {
            System.setOut(stdout);
            System.setErr(stderr);
        }
    }

    static List<String> files(Path dir) throws Exception {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void writesGlbGltfAndBvhAndNothingElse(@TempDir Path dir) throws Exception {
        for (String name : List.of("loop.glb", "loop.gltf", "loop.bvh")) {
            Result r = run("export", "--task", "height", "--seconds", "0.5", "--out", dir.resolve(name).toString());
            assertEquals(0, r.code(), r.err());
            // 0.5 s at the default 60 Hz: samples at 0, 1/60, ..., 30/60
            assertTrue(r.out().contains("31 samples at 60.0 Hz"), r.out());
        }
        assertEquals(List.of("loop.bin", "loop.bvh", "loop.glb", "loop.gltf"), files(dir), "no temporary file left");
        byte[] glb = Files.readAllBytes(dir.resolve("loop.glb"));
        assertEquals("glTF", new String(glb, 0, 4, StandardCharsets.US_ASCII));
        assertTrue(Files.readString(dir.resolve("loop.bvh")).startsWith("HIERARCHY\nROOT upper_arm"));
    }

    @Test
    void malformedRequestsAreRefusedInOneLineBeforeSimulatingAndLeaveNoFile(@TempDir Path dir) throws Exception {
        Path notAFolder = Files.writeString(dir.resolve("plain.txt"), "a file, not a folder");
        String[][] requests = {
            {"--format", "fbx", "--out", dir.resolve("a.fbx").toString()},
            {"--out", dir.resolve("a.obj").toString()},
            {"--format", "bvh", "--out", dir.resolve("a.glb").toString()},
            {"--out", notAFolder.resolve("a.glb").toString()},
            {"--out", dir.toString() + "/"},
            {"--seconds", "0", "--out", dir.resolve("a.glb").toString()},
            {"--rate", "0", "--out", dir.resolve("a.glb").toString()},
            {"--seconds", "0.01", "--out", dir.resolve("a.glb").toString()},
        };
        String[] named = {"--format", "--out", "--out", "--out", "--out", "--seconds", "--rate", "--seconds"};
        for (int i = 0; i < requests.length; i++) {
            String[] args = Stream.concat(Stream.of("export", "--task", "height"), Stream.of(requests[i])).toArray(String[]::new);
            Result r = run(args);
            String what = String.join(" ", requests[i]);
            assertEquals(2, r.code(), what + ": " + r.err());
            assertEquals(1, r.err().strip().lines().count(), "one line: " + r.err());
            assertTrue(r.err().startsWith("handsim export: ") && r.err().contains(named[i]), "names " + named[i] + ": " + r.err());
            assertFalse(r.out().contains("height task"), "refused before the scene is opened: " + r.out());
        }
        assertEquals(List.of("plain.txt"), files(dir), "nothing written");
    }

    @Test
    void demoAndEvaluateWriteTheirRunsAnimation(@TempDir Path dir) throws Exception {
        Result demo = run("demo", "--headless", "--loops", "1", "--seed", "1", "--out", dir.resolve("demo").toString(), "--export",
                dir.resolve("demo.glb").toString());
        assertEquals(0, demo.code(), demo.err());
        assertTrue(demo.out().contains("demo.glb") && demo.out().contains("samples at 60.0 Hz"), demo.out());
        assertEquals("glTF", new String(Files.readAllBytes(dir.resolve("demo.glb")), 0, 4, StandardCharsets.US_ASCII));
        Result evaluate = run("evaluate", "--task", "height", "--episodes", "1", "--loops", "1", "--workers", "1", "--export",
                dir.resolve("episode.bvh").toString());
        assertEquals(0, evaluate.code(), evaluate.err());
        String bvh = Files.readString(dir.resolve("episode.bvh"));
        // a frame every 1/60 s from the first tick to the episode's end
        int frames = Integer.parseInt(bvh.lines().filter(l -> l.startsWith("Frames:")).findFirst().orElseThrow().substring(7).strip());
        assertTrue(frames > 60, "over a second of frames: " + frames);
        Result many = run("evaluate", "--episodes", "2", "--export", dir.resolve("two.glb").toString());
        assertEquals(2, many.code());
        assertTrue(many.err().contains("--export goes with one episode"), many.err());
        assertFalse(Files.exists(dir.resolve("two.glb")));
    }
}
