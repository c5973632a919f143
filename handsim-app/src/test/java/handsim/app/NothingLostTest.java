package handsim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import handsim.config.Home;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The refusals of "nothing lost", through the real commands and before any work: an output that
 * is an input or another output (family 1), a card output target that cannot be written (5),
 * values beyond physical ranges (6) and values nobody checked (7). Each exits with status 2 in
 * one line naming the file and the reason, prints nothing of a simulation and changes no file.
 * The cases that need other processes are {@link NothingLostProcessesTest}'s.
 */
@Tag("fast")
class NothingLostTest {

    @TempDir
    Path tmp;

    /** Runs the command, asserts the one-line refusal naming {@code parts}, no simulation begun and every file under tmp kept. */
    private CliRun refused(List<String> args, String... parts) throws IOException {
        Map<String, String> before = CliRun.contents(tmp);
        CliRun r = CliRun.of(args.toArray(String[]::new)).assertRefused(2, parts);
        assertEquals(before, CliRun.contents(tmp), "no file written or changed");
        assertFalse(r.out().lines().anyMatch(l -> l.matches("(episode \\d+|throw +\\d+/|hold \\(warm-up|trial \\d+).*")),
                "refused before any simulation: " + r.out());
        return r;
    }

    private Path copy(Path shipped, String name) throws IOException {
        return Files.copy(shipped, tmp.resolve(name));
    }

    @Test
    void anOutputThatIsAnInputOfTheRunIsRefused() throws IOException {
        Path policy = copy(Home.resolve("models/policies/height-sphere.json"), "P.json");
        refused(List.of("evaluate", "--controller", "learned", "--policy", policy.toString(), "--json", policy.toString(), "--loops", "1"),
                "--json " + policy, "is the file of --policy, an input of this run");
        Path model = copy(Home.defaultModel(), "M.json");
        refused(List.of("info", "--model", model.toString(), "--json", model.toString()), "is the file of --model");
        Path goals = Files.writeString(tmp.resolve("G.json"), "{\"heights\": [1.2]}");
        refused(List.of("evaluate", "--goals", goals.toString(), "--csv", goals.toString(), "--loops", "1"), "is the file of --goals");
        Path run = Files.createDirectories(tmp.resolve("run"));
        Files.writeString(run.resolve("metrics.csv"), handsim.learn.MetricsCsv.HEADER + "\n1,1,1,0.5,0.5,0.1,,,0,false,,1.000\n");
        refused(List.of("curves", run.toString(), "--out", run.resolve("metrics.csv").toString()), "--out " + run.resolve("metrics.csv"),
                "an input of this run");
        Path params = Files.writeString(tmp.resolve("result.json"), "{\"t0\": 0, \"t1\": 0.1, \"vp\": 0.003, \"t2\": 0.15, \"t3\": 0.35, "
                + "\"vs\": 0.01}");
        refused(List.of("cards", "snap", "--mesh", "coarse", "--no-frames", "--params", params.toString(), "--out", tmp.toString()),
                "--out " + tmp + " (its result.json) is the file of --params");
        // the shipped inputs under models/ and configs/ are never written
        Path shipped = Home.resolve("models/policies/height-sphere.json");
        String hash = CliRun.contents(shipped.getParent()).get("height-sphere.json");
        refused(List.of("evaluate", "--loops", "1", "--json", shipped.toString()), "is under the project's models/");
        assertEquals(hash, CliRun.contents(shipped.getParent()).get("height-sphere.json"));
    }

    @Test
    void aRecordedSpecAndThePoliciesItNamesAreInputsOfTheRunThatRepeatsIt() throws IOException {
        // evaluate --spec reads the record and the policy files it names (checked against their SHA-256): none may be an output
        Path policy = copy(Home.resolve("models/policies/height-sphere.json"), "P.json");
        Path spec = Files.writeString(tmp.resolve("S.json"), "{\"task\": \"height\", \"controller\": \"learned\", \"object\": "
                + "\"sphere\", \"plan\": false, \"seed\": 1, \"loops\": 1, \"episodes\": 1, \"tests\": 1, \"policies\": {\"policy\": "
                + "{\"file\": \"" + policy + "\", \"sha256\": \"" + handsim.config.ReadLog.sha256(Files.readAllBytes(policy)) + "\"}}, "
                + "\"configs\": {}}");
        refused(List.of("evaluate", "--spec", spec.toString(), "--json", spec.toString()), "--json " + spec,
                "is the file of --spec, an input of this run");
        refused(List.of("evaluate", "--spec", spec.toString(), "--csv", policy.toString()), "--csv " + policy,
                "is the policy recorded in --spec " + spec + ", an input of this run");
    }

    @Test
    void twoOutputsOfOneRunOnOnePathAreRefused() throws IOException {
        Path f = tmp.resolve("F");
        refused(List.of("evaluate", "--loops", "1", "--csv", f.toString(), "--json", f.toString()), "is also written as --json " + f);
        refused(List.of("evaluate", "--loops", "1", "--json", f + ".json", "--csv", f + ".json.episodes.jsonl"),
                "is also written as --json " + f + ".json.episodes.jsonl");
        Path glb = tmp.resolve("a/x.glb");
        refused(List.of("evaluate", "--loops", "1", "--export", glb.toString(), "--json", glb.toString()),
                "--json " + glb, "--export " + glb, "is also written as"); // whichever is checked second names the first
        assertFalse(Files.exists(glb.getParent()), "the folder the refused run made is gone again");
    }

    @Test
    void aCardOutputTargetThatCannotBeWrittenIsRefusedBeforeTheSimulation() throws Exception {
        Path file = Files.writeString(tmp.resolve("file"), "x");
        refused(List.of("cards", "snap", "--mesh", "coarse", "--no-frames", "--out", file.resolve("run").toString()), "is a file, not a folder");
        Path longName = tmp.resolve("n".repeat(260));
        refused(List.of("cards", "snap", "--mesh", "coarse", "--no-frames", "--out", longName.toString()),
                "has a name of 260 bytes, more than the 255 a file name may have");
        refused(List.of("cards", "optimize", "--sleight", "snap", "--trials", "1", "--seed", "1", "--mesh", "coarse", "--no-frames",
                "--out", file.toString()), "is a file, not a folder");
        // a read-only folder: a read-only tmpfs where one can be mounted (as root, who may write anywhere else)
        Path ro = Files.createDirectories(tmp.resolve("ro"));
        Process mount = new ProcessBuilder("mount", "-t", "tmpfs", "-o", "size=64k,ro", "tmpfs", ro.toString()).redirectErrorStream(true).start();
        mount.getInputStream().readAllBytes();
        assumeTrue(mount.waitFor(10, TimeUnit.SECONDS) && mount.exitValue() == 0, "no read-only tmpfs can be mounted here");
        try {
            refused(List.of("cards", "snap", "--mesh", "coarse", "--no-frames", "--out", ro.resolve("run").toString()),
                    "cannot be written", "Read-only file system");
        } finally {
            new ProcessBuilder("umount", ro.toString()).start().waitFor(10, TimeUnit.SECONDS);
        }
    }

    @Test
    void cardValuesBeyondPhysicalRangesAreRefusedBeforeTheSimulation() throws IOException {
        Path params = Files.writeString(tmp.resolve("p.json"), "{\"t0\": 0, \"t1\": 0.1, \"vp\": 0.003, \"t2\": 0.15, \"t3\": 0.35, "
                + "\"vs\": 1e6}");
        refused(List.of("cards", "snap", "--mesh", "coarse", "--no-frames", "--params", params.toString()),
                "vs must be a speed in [0, 2] m/s, got 1000000");
        List<String> optimize = List.of("cards", "optimize", "--sleight", "snap", "--trials", "1", "--seed", "1", "--mesh", "coarse",
                "--no-frames", "--out", tmp.resolve("S").toString(), "--set");
        refused(concat(optimize, "snap.params.vs=1e6"), "vs must be a speed in [0, 2] m/s, got 1000000");
        refused(concat(optimize, "solver.gravity=[0, 0, -1e9]"), "configs/cards/solver.json: gravity: its magnitude must be at most 100");
        assertFalse(Files.exists(tmp.resolve("S")), "no study folder for refused settings");
    }

    private static List<String> concat(List<String> args, String... more) {
        List<String> all = new java.util.ArrayList<>(args);
        all.addAll(List.of(more));
        return all;
    }

    @Test
    void valuesNobodyCheckedAreRefused() throws IOException {
        Path policy = tmp.resolve("P.json");
        Files.writeString(policy, Files.readString(Home.resolve("models/policies/height-sphere.json"))
                .replaceFirst("\"weights\" : \\[ \\[ [^,]+,", "\"weights\" : [ [ 1e308,"));
        refused(List.of("evaluate", "--controller", "learned", "--policy", policy.toString(), "--loops", "1"),
                "weights[0]: entry 0 is 1E+308: a policy's weights and biases lie within [-10000, 10000]");
        Path goals = Files.writeString(tmp.resolve("G.json"), "{\"heights\": [1.2], \"heights\": [1.3]}");
        refused(List.of("evaluate", "--goals", goals.toString(), "--loops", "1"), "the key \"heights\" appears twice in one object");
        Path model = tmp.resolve("M.json");
        Files.writeString(model, Files.readString(Home.defaultModel()).replaceFirst("\"rangeDeg\": \\[0, 150\\]", "\"rangeDeg\": [-1e6, 1e6]"));
        refused(List.of("info", "--model", model.toString()), "rangeDeg: [-1000000, 1000000] degrees is beyond what a human "
                + "elbow_flexion reaches, [-20, 170]");
    }
}
