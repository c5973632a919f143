package handsim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.config.Json;
import handsim.model.ModelLoader;
import handsim.sim.ObjectSpec;
import handsim.sim.SimConfig;
import handsim.scene.HeightControl;
import handsim.task.HeightGoals;
import handsim.task.HeightTask;
import handsim.scene.InteractiveScene;
import handsim.scene.SceneSetup;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.Consumer;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Faults injected into the commands' inputs and outputs: output paths that are folders, under a
 * file or unwritable; physics out of its sanity ranges; runs racing for a folder; a world that
 * diverges; an object no hand catches. Each case asserts the exit status, the one-line message
 * and the files left behind (training runs: {@link FaultInjectionTrainingTest}).
 */
@Tag("slow")
class FaultInjectionTest {

    @TempDir
    Path tmp;

    @Test
    void runsStartedInTheSameSecondEachClaimAFolderOfTheirOwn() throws Exception {
        int runs = 8;
        CyclicBarrier start = new CyclicBarrier(runs);
        ExecutorService pool = Executors.newFixedThreadPool(runs);
        Set<Path> claimed = new HashSet<>();
        try {
            List<Future<Path>> claims = new java.util.ArrayList<>();
            for (int i = 0; i < runs; i++) {
                claims.add(pool.submit(() -> {
                    start.await();
                    return RunFolders.claim(tmp, "--runs", "demo", "sphere", 9);
                }));
            }
            for (Future<Path> f : claims) {
                claimed.add(f.get());
            }
        } finally {
            pool.shutdown();
        }
        assertEquals(runs, claimed.size(), "no two runs share a folder: " + claimed);
        for (Path dir : claimed) {
            assertTrue(Files.isDirectory(dir), dir.toString());
            // same second, same name: the later ones get -2, -3, ...; the legend of curves drops it with the time
            assertTrue(dir.getFileName().toString().matches("demo__sphere__9__\\d{8}-\\d{6}(-[2-8])?"), dir.toString());
            assertEquals("demo__sphere__9", RunFolders.withoutStartTime(dir));
        }
    }

    @Test
    void aRunFolderGivenWithOutThatHoldsFilesIsRefusedAndKeptAsItWas() throws IOException {
        Path earlier = Files.createDirectories(tmp.resolve("earlier"));
        Files.writeString(earlier.resolve("summary.json"), "{\"throws\": 20}");
        Map<String, String> before = CliRun.contents(tmp);
        CliRun.of("demo", "--headless", "--out", earlier.toString()).assertRefused(2, "--out", "already holds files");
        assertEquals(before, CliRun.contents(tmp));
    }

    @Test
    void outputPathsAreCheckedBeforeAnyWorkAndNothingIsWritten() throws IOException {
        Path folder = Files.createDirectories(tmp.resolve("folder"));
        Path file = Files.writeString(tmp.resolve("file.txt"), "x");
        Path underFile = file.resolve("out.json");
        // /proc takes no new files, not even for root (the tests may run as root, whom file modes do not stop)
        Path unwritable = Path.of("/proc/handsim-fault-test/out.json");
        Map<String, String> before = CliRun.contents(tmp);
        CliRun.of("evaluate", "--json", folder.toString()).assertRefused(2, "--json", "is a folder");
        CliRun.of("evaluate", "--csv", underFile.toString()).assertRefused(2, "--csv", file + " is a file, not a folder");
        CliRun.of("evaluate", "--plot", unwritable.toString()).assertRefused(2, "--plot", "cannot be written");
        CliRun.of("info", "--json", folder.toString()).assertRefused(2, "--json", "is a folder");
        CliRun.of("bench", "--json", unwritable.toString()).assertRefused(2, "--json", "cannot be written");
        CliRun.of("curves", tmp.toString(), "--out", folder.toString()).assertRefused(2, "--out", "is a folder");
        CliRun.of("render", "--out", file.toString()).assertRefused(2, "--out", "is a file, not a folder");
        CliRun.of("view", "--screenshot", folder.toString()).assertRefused(2, "--screenshot", "is a folder");
        CliRun.of("demo", "--headless", "--runs", file.toString()).assertRefused(2, "--runs", "is a file, not a folder");
        CliRun.of("train", "--config", "configs/train/height.json", "--runs", underFile.toString())
                .assertRefused(2, "--runs", "is a file, not a folder");
        assertEquals(before, CliRun.contents(tmp), "nothing written, nothing half-written");
    }

    @Test
    void anEvaluationOfNoLoopsWritesNullWhereAFigureHasNoValueAndPrintsNoNaN() throws IOException {
        Path json = tmp.resolve("none.json");
        CliRun r = CliRun.of("evaluate", "--loops", "0", "--workers", "1", "--json", json.toString());
        assertEquals(0, r.status(), r.toString());
        String text = Files.readString(json);
        assertFalse(text.contains("NaN") || text.contains("Infinity"), text);
        JsonNode summary = new ObjectMapper().readTree(text); // strict JSON
        assertTrue(summary.get("height_error_mean").isNull(), "a mean over no throws: " + summary);
        assertEquals(0, summary.get("throws").asInt());
        assertFalse(r.out().contains("NaN"), "the console summary has no NaN either: " + r.out());
    }

    @Test
    void physicsOutOfItsSanityRangesIsRefusedNamingTheFieldTheValueAndTheRange() {
        assertRefused(sim(j -> j.set("gravity", Json.array(0, -1e9, 0))), "gravity", "1E+9", "[0.5, 100]");
        assertRefused(sim(j -> j.put("timeStep", 0.05)), "timeStep", "0.05", "[0.000001, 0.01]");
        assertRefused(sim(j -> ((ObjectNode) j.get("contact")).put("stiffness", 1e12)), "contact.stiffness", "1E+12", "1E+8");
        assertRefused(object(j -> j.put("mass", 1e300)), "mass", "1E+300", "[0.001, 10]");
        assertRefused(object(j -> ((ObjectNode) j.get("shapes").get(0)).put("radius", 5.0)), "shapes[0].radius", "5", "[0.0001, 2]");
        assertRefused(model(j -> ((ObjectNode) j.get("bodies").get(1)).put("mass", 1e30)), "bodies[1].mass", "1E+30", "100");
        ConfigException goals = assertThrows(ConfigException.class, () -> HeightTask.Config.parse(Json.of("height.json",
                edited(Home.resolve("configs/tasks/height.json"), j -> j.set("goalRange", Json.array(1, 1e9))))));
        assertTrue(goals.getMessage().contains("goalRange") && goals.getMessage().contains("(0.7, 3.0)"), goals.getMessage());
        CliRun.of("demo", "--headless", "--heights", "1:1e9").assertRefused(2, "--heights", "1:1e9", "0.7 < LOW <= HIGH < 3.0");
        CliRun.of("evaluate", "--throw-height", "50").assertRefused(2, "--throw-height", "50", "(0.7, 3.0)");
    }

    /**
     * A world within the sanity ranges can still diverge: a 5 ms step (25 times the paper's) is
     * too coarse for the arm's PD servos, and the palm spins up within the first 0.1 s.
     */
    @Test
    void aDivergingWorldEndsEvaluateAndDemoInOneLineNamingSeedLoopAndWhat() throws IOException {
        Path home = home(Map.of("configs/sim.json", j -> j.put("timeStep", 0.005)));
        Path json = tmp.resolve("diverged.json"), runs = tmp.resolve("runs");
        withHome(home, () -> {
            CliRun.of("evaluate", "--loops", "1", "--workers", "1", "--json", json.toString())
                    .assertRefused(1, "the simulation diverged", "seed 1, loop 0", "spins at");
            CliRun.of("demo", "--headless", "--loops", "1", "--runs", runs.toString())
                    .assertRefused(1, "the simulation diverged", "seed 1, loop 0");
        });
        assertFalse(Files.exists(json), "no summary of a run that diverged");
        // the demo's run folder is given up (the runs folder itself is made only for a run that starts)
        if (Files.exists(runs)) {
            try (Stream<Path> left = Files.list(runs)) {
                assertEquals(List.of(), left.toList(), "the demo's run folder is given up");
            }
        }
    }

    /**
     * A 10 kg sphere (the heaviest object the ranges allow) slips through the hand: demo gives up
     * after configs/episode.json maxFailedThrowIns throw-ins in a row (2 here) and says why, and
     * the viewer's scene stops throwing in and says so on screen.
     */
    @Test
    void demoAndTheViewerGiveUpAfterTheStatedNumberOfFailedThrowIns() throws IOException {
        Path home = home(Map.of("configs/objects/sphere.json", j -> j.put("mass", 10.0),
                "configs/episode.json", j -> j.put("maxFailedThrowIns", 2)));
        Path runs = tmp.resolve("runs");
        withHome(home, () -> {
            CliRun.of("demo", "--headless", "--loops", "1", "--runs", runs.toString())
                    .assertRefused(1, "gave up after 2 throw-ins in a row", "maxFailedThrowIns");
            ShippedScenes catalog = new ShippedScenes(new HeightGoals(1.1, 1.3), new HeightControl(0.05, 0.8, 1.7), ControllerOptions.Choice.SHIPPED);
            try (InteractiveScene scene = catalog.open(new SceneSetup("height", "sphere", "nominal", 1)).scene()) {
                for (int i = 0; i < 200 && !scene.status().containsKey("stopped"); i++) {
                    scene.advance(0.1);
                }
                String stopped = scene.status().get("stopped");
                assertTrue(stopped != null && stopped.contains("2 throw-ins in a row were not caught"), scene.status().toString());
                double t = scene.time();
                scene.advance(1.0);
                assertEquals(t, scene.time(), 0, "nothing more is thrown in");
            }
        });
    }

    // ---- helpers ----------------------------------------------------------------------------

    private static void assertRefused(Runnable load, String... parts) {
        ConfigException e = assertThrows(ConfigException.class, load::run);
        for (String p : parts) {
            assertTrue(e.getMessage().contains(p), "the message names \"" + p + "\": " + e.getMessage());
        }
    }

    private static Runnable sim(Consumer<ObjectNode> edit) {
        return () -> SimConfig.parse(Json.of("sim.json", edited(Home.resolve("configs/sim.json"), edit)));
    }

    private static Runnable object(Consumer<ObjectNode> edit) {
        return () -> ObjectSpec.parse(Json.of("sphere.json", edited(Home.resolve("configs/objects/sphere.json"), edit)));
    }

    private static Runnable model(Consumer<ObjectNode> edit) {
        return () -> ModelLoader.parse(Json.of("arm_hand.json", edited(Home.defaultModel(), edit)));
    }

    private static ObjectNode edited(Path file, Consumer<ObjectNode> edit) {
        ObjectNode j = (ObjectNode) Json.load(file).node().deepCopy();
        edit.accept(j);
        return j;
    }

    /** A copy of the project's models/ and configs/ with some files edited: a home for -Dhandsim.home. */
    private Path home(Map<String, Consumer<ObjectNode>> edits) throws IOException {
        Path home = tmp.resolve("home");
        for (String part : List.of("models", "configs")) {
            CliRun.copyTree(Home.resolve(part), home.resolve(part));
        }
        for (Map.Entry<String, Consumer<ObjectNode>> e : edits.entrySet()) {
            Path file = home.resolve(e.getKey());
            Files.writeString(file, Json.pretty(edited(file, e.getValue())));
        }
        return home;
    }

    /** Runs {@code body} with handsim's data read from {@code home} (the test classes run one at a time). */
    private static void withHome(Path home, Runnable body) {
        String before = System.getProperty("handsim.home");
        System.setProperty("handsim.home", home.toString());
        try {
            body.run();
        } finally {
            if (before == null) {
                System.clearProperty("handsim.home");
            } else {
                System.setProperty("handsim.home", before);
            }
        }
    }
}
