package handsim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import handsim.config.Home;
import handsim.config.Json;
import handsim.train.TrainRun;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * "Nothing lost" where other processes come in, through the launcher ({@code scripts/handsim},
 * on this build's classes): two processes racing on one folder, SIGTERM and SIGINT to the
 * launcher, a full disk under a card trial; and, in this JVM, a resume from another run's
 * checkpoint and a study whose trials go past their budget.
 */
@Tag("slow")
class NothingLostProcessesTest {

    /** A training run of one-throw episodes, a checkpoint after each (as the fault injection of training uses). */
    private static final List<String> TINY = List.of("--set", "training.parallelEpisodes=1", "--set", "training.maxDecisionsPerEpisode=1",
            "--set", "training.checkpointEveryEpisodes=1", "--set", "exploration.warmupSteps=1", "--set", "ddpg.batchSize=2",
            "--set", "ddpg.replayCapacity=100", "--set", "run.workers=1", "--set", "run.progressSeconds=0.001");

    @TempDir
    Path tmp;

    /** The launcher running {@code args} on this build's classes, its output to {@code log}. */
    private static Process launcher(Path log, Path home, String... args) throws IOException {
        List<String> command = new ArrayList<>(List.of("bash", Home.resolve("scripts/handsim").toString()));
        command.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile());
        pb.environment().put("HANDSIM_CLASSPATH", System.getProperty("java.class.path"));
        pb.environment().put("HANDSIM_HOME", home.toString());
        pb.environment().put("OMP_NUM_THREADS", "1");
        pb.environment().remove("DISPLAY");
        return pb.start();
    }

    private static Process launcher(Path log, String... args) throws IOException {
        return launcher(log, Home.root(), args);
    }

    /** Waits until {@code log} shows a line matching {@code regex} (or the process ends: then fails). */
    private static void awaitLine(Process p, Path log, String regex) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(300);
        while (!Files.exists(log) || Files.readAllLines(log).stream().noneMatch(l -> l.matches(regex))) {
            assertTrue(p.isAlive(), "ended before printing " + regex + ": " + (Files.exists(log) ? Files.readString(log) : ""));
            assertTrue(System.nanoTime() < deadline, "no " + regex + " in 300 s");
            Thread.sleep(50);
        }
    }

    private static void signal(Process p, String name) throws Exception {
        assertEquals(0, new ProcessBuilder("kill", "-" + name, Long.toString(p.pid())).start().waitFor());
    }

    private static int exit(Process p) throws InterruptedException {
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), "ended");
        return p.exitValue();
    }

    @Test
    void aSecondProcessOnAHeldFolderIsRefusedAtOnceNamingTheFirst() throws Exception {
        // how long this JVM takes to start and say its version: the refusal may take that and a second more
        long t0 = System.nanoTime();
        assertEquals(0, exit(launcher(tmp.resolve("version.log"), "--version")));
        double startup = (System.nanoTime() - t0) * 1e-9;

        Path run = tmp.resolve("run");
        Process first = launcher(tmp.resolve("first.log"), "demo", "--headless", "--loops", "4", "--seed", "1", "--out", run.toString());
        try {
            while (!Files.exists(run.resolve(".handsim.lock")) || Files.size(run.resolve(".handsim.lock")) == 0) {
                assertTrue(first.isAlive(), Files.readString(tmp.resolve("first.log")));
                Thread.sleep(20);
            }
            t0 = System.nanoTime();
            Path secondLog = tmp.resolve("second.log");
            int second = exit(launcher(secondLog, "demo", "--headless", "--loops", "4", "--seed", "2", "--out", run.toString()));
            double refusal = (System.nanoTime() - t0) * 1e-9;
            assertEquals(2, second, Files.readString(secondLog));
            List<String> said = Files.readAllLines(secondLog);
            assertEquals(1, said.size(), "one line: " + said);
            assertTrue(said.get(0).startsWith("handsim demo: --out " + run + " is in use by another handsim process (pid " + first.pid()
                    + ", scripts/handsim demo --headless --loops 4 --seed 1 --out " + run + ", started "), said.get(0));
            assertTrue(refusal < startup + 1, "refused in " + refusal + " s, before loading anything (the JVM starts in " + startup + " s)");
        } finally {
            assertEquals(0, exit(first), Files.readString(tmp.resolve("first.log")));
        }
        // the first run is whole: its summary is seed 1's
        assertEquals(1, Json.load(run.resolve("summary.json")).integer("seed"));
        assertEquals(4, Json.load(run.resolve("summary.json")).integer("throws"));
        assertFalse(Files.exists(run.resolve(".handsim.lock")), "released");
    }

    @Test
    void sigtermToTheLauncherStopsTrainingWithACheckpointAndLeavesNoJvm() throws Exception {
        List<String> train = new ArrayList<>(List.of("train", "--config", Home.resolve("configs/train/height.json").toString(),
                "--set", "training.episodes=6"));
        train.addAll(TINY);
        Path reference = tmp.resolve("reference");
        List<String> args = new ArrayList<>(train);
        args.addAll(List.of("--runs", reference.toString()));
        assertEquals(0, CliRun.of(args.toArray(String[]::new)).status());

        Path runs = tmp.resolve("stopped");
        args = new ArrayList<>(train);
        args.addAll(List.of("--runs", runs.toString()));
        Path log = tmp.resolve("train.log");
        Process launcher = launcher(log, args.toArray(String[]::new));
        awaitLine(launcher, log, "\\[#+\\.*\\] 2/6 episodes.*");
        List<ProcessHandle> started = launcher.descendants().toList();
        assertFalse(started.isEmpty(), "the launcher supervises training: the JVM is its child");
        launcher.destroy(); // SIGTERM to the launcher
        assertEquals(143, exit(launcher), Files.readString(log));
        for (ProcessHandle h : started) {
            h.onExit().get(10, TimeUnit.SECONDS); // gone with the launcher (else this times out)
        }
        String said = Files.readString(log);
        assertTrue(said.contains("handsim train: stopped by SIGTERM: a checkpoint at episode "), said);

        Path run;
        try (Stream<Path> dirs = Files.list(runs)) {
            run = dirs.findFirst().orElseThrow();
        }
        assertTrue(Files.exists(run.resolve(TrainRun.CHECKPOINT)));
        assertEquals(0, CliRun.of("train", "--resume", run.toString()).status());
        // the stopped and resumed run is the uninterrupted one, row for row (all but the wall time)
        Path referenceRun;
        try (Stream<Path> dirs = Files.list(reference)) {
            referenceRun = dirs.findFirst().orElseThrow();
        }
        assertEquals(withoutWallTime(referenceRun.resolve(TrainRun.METRICS)), withoutWallTime(run.resolve(TrainRun.METRICS)));
    }

    /** Whether this JVM was started with SIGINT ignored (bit 2 of SigIgn in /proc/self/status). */
    private static boolean sigintIgnored() throws IOException {
        for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
            if (line.startsWith("SigIgn:")) {
                return (Long.parseUnsignedLong(line.substring(7).trim(), 16) & (1L << 1)) != 0;
            }
        }
        return false;
    }

    private static List<String> withoutWallTime(Path metrics) throws IOException {
        return Files.readAllLines(metrics).stream().map(l -> l.substring(0, l.lastIndexOf(','))).toList();
    }

    @Test
    void ctrlCDuringADemoWritesTheThrowsMadeMarkedInterrupted() throws Exception {
        // a process started with SIGINT ignored (a background job of a script, nohup) passes the
        // ignoring on to its children, and neither bash nor the JVM may take it back: Ctrl-C cannot reach them
        assumeFalse(sigintIgnored(), "this test runs with SIGINT ignored, so no child can receive it");
        Path run = tmp.resolve("run");
        Path log = tmp.resolve("demo.log");
        Process demo = launcher(log, "demo", "--headless", "--loops", "200", "--out", run.toString());
        awaitLine(demo, log, "throw +2/200: .*");
        signal(demo, "INT");
        assertEquals(130, exit(demo), Files.readString(log));
        Json summary = Json.load(run.resolve("summary.json"));
        int made = summary.integer("throws");
        assertTrue(made >= 2 && made < 200, made + " throws");
        assertEquals("SIGINT after " + made + " of 200 throws", summary.string("interrupted"));
        assertEquals(made + 1, Files.readAllLines(run.resolve("loops.csv")).size(), "a row per throw made");
        assertTrue(Files.size(run.resolve("apex.png")) > 1000);
    }

    @Test
    void sigtermDuringAnEvaluationMarksItsJsonAndTheSameCommandGoesOn() throws Exception {
        Path json = tmp.resolve("F.json");
        String[] evaluate = {"evaluate", "--episodes", "3", "--loops", "2", "--workers", "1", "--json", json.toString()};
        Path log = tmp.resolve("evaluate.log");
        Process p = launcher(log, evaluate);
        awaitLine(p, log, "episode 2 loop .*");
        signal(p, "TERM");
        assertEquals(143, exit(p), Files.readString(log));
        Json marked = Json.load(json);
        assertEquals("SIGTERM", marked.string("interrupted"));
        assertTrue(marked.integer("episodes_finished") >= 1, "episode 1 was finished");
        CliRun again = CliRun.of(evaluate);
        assertEquals(0, again.status(), again.toString());
        Json done = Json.load(json);
        assertFalse(done.has("interrupted"));
        assertEquals(marked.integer("episodes_finished"), done.integer("episodes_resumed"), "the finished episodes read back, not run again");
    }

    @Test
    void aFullDiskFailsACardTrialsWriteInOneLineNamingTheFileAndLeavesNoTemporaryFile() throws Exception {
        Path home = tmp.resolve("home");
        for (String part : List.of("models", "configs")) {
            CliRun.copyTree(Home.resolve(part), home.resolve(part));
        }
        Path snap = home.resolve("configs/cards/snap.json");
        Files.writeString(snap, Json.pretty(Json.withOverrides("snap.json", Json.load(snap).node(), Map.of("trial.duration", "0.2",
                "hold.warmup", "0.1", "fingertip.softLayers", "1", "params",
                "{\"t0\": 0, \"t1\": 0.05, \"vp\": 0.002, \"t2\": 0.05, \"t3\": 0.15, \"vs\": 0.01}"))));
        Path disk = Files.createDirectories(tmp.resolve("disk"));
        // a 32 kB tmpfs where one can be mounted (as root), else a file-size limit of 32 kB on the process
        Process mount = new ProcessBuilder("mount", "-t", "tmpfs", "-o", "size=32k", "tmpfs", disk.toString()).redirectErrorStream(true).start();
        mount.getInputStream().readAllBytes();
        boolean mounted = mount.waitFor(10, TimeUnit.SECONDS) && mount.exitValue() == 0;
        Path log = tmp.resolve("snap.log");
        try {
            Process p;
            if (mounted) {
                p = launcher(log, home, "cards", "snap", "--mesh", "coarse", "--no-frames", "--out", disk.resolve("run").toString());
            } else {
                ProcessBuilder pb = new ProcessBuilder("bash", "-c", "ulimit -f 32; exec \"$0\" \"$@\"", Home.resolve("scripts/handsim").toString(),
                        "cards", "snap", "--mesh", "coarse", "--no-frames", "--out", disk.resolve("run").toString())
                        .redirectErrorStream(true).redirectOutput(log.toFile());
                pb.environment().put("HANDSIM_CLASSPATH", System.getProperty("java.class.path"));
                pb.environment().put("HANDSIM_HOME", home.toString());
                p = pb.start();
            }
            assertEquals(1, exit(p), Files.readString(log));
            List<String> errors = Files.readAllLines(log).stream().filter(l -> l.startsWith("handsim snap: ")).toList();
            assertEquals(List.of("handsim snap: " + disk.resolve("run/trajectory.json") + ": cannot write it: "
                    + (mounted ? "No space left on device" : "File too large")), errors);
            assertEquals(List.of(), CliRun.temporaryFiles(disk), "no temporary file left");
            assertFalse(Files.exists(disk.resolve("run/result.json")), "no result without its trajectory");
        } finally {
            if (mounted) {
                new ProcessBuilder("umount", disk.toString()).start().waitFor(10, TimeUnit.SECONDS);
            }
        }
    }

    @Test
    void aResumeFromAnotherRunsCheckpointIsRefusedNamingTheField() throws Exception {
        List<String> height = new ArrayList<>(List.of("train", "--config", "configs/train/height.json", "--runs", tmp.resolve("h").toString(),
                "--set", "training.episodes=2"));
        height.addAll(TINY);
        assertEquals(0, CliRun.of(height.toArray(String[]::new)).status());
        List<String> box = new ArrayList<>(List.of("train", "--config", "configs/train/box.json", "--runs", tmp.resolve("b").toString(),
                "--set", "training.episodes=2", "--session-episodes", "1"));
        box.addAll(TINY);
        assertEquals(0, CliRun.of(box.toArray(String[]::new)).status());
        Path heightRun, boxRun;
        try (Stream<Path> h = Files.list(tmp.resolve("h")); Stream<Path> b = Files.list(tmp.resolve("b"))) {
            heightRun = h.findFirst().orElseThrow();
            boxRun = b.findFirst().orElseThrow();
        }
        Files.copy(heightRun.resolve(TrainRun.CHECKPOINT), boxRun.resolve(TrainRun.CHECKPOINT), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        Map<String, String> before = CliRun.contents(boxRun);
        CliRun.of("train", "--resume", boxRun.toString()).assertRefused(2, boxRun.resolve(TrainRun.CHECKPOINT) + " belongs to another run: "
                + "its task is \"height\", this run's is \"box\"");
        assertEquals(before, CliRun.contents(boxRun), "nothing was changed");
    }

    @Test
    void aStudyWhoseTrialsGoPastTheirBudgetCompletesWithThemFailed() throws Exception {
        Path config = Files.writeString(tmp.resolve("study.json"), """
                {"objectives": [{"name": "objective", "direction": "minimize"}],
                 "params": [{"name": "t0", "low": 0.0, "high": 0.02}, {"name": "t1", "low": 0.02, "high": 0.04},
                            {"name": "vp", "low": 0.001, "high": 0.004}, {"name": "t2", "low": 0.04, "high": 0.05},
                            {"name": "t3", "low": 0.05, "high": 0.1}, {"name": "vs", "low": 0.005, "high": 0.04}],
                 "parallelTrials": 1, "sampler": {"nStartupTrials": 2}}
                """);
        Path out = tmp.resolve("S");
        // 1000 Newton iterations a simulated second: 100 for the 0.1 s trial; the coarse trials of seed 1 take 94 to 195
        CliRun r = CliRun.of("cards", "optimize", "--sleight", "snap", "--trials", "3", "--seed", "1", "--config", config.toString(),
                "--out", out.toString(), "--mesh", "coarse", "--no-frames", "--set", "snap.trial.duration=0.1", "--set", "snap.hold.warmup=0.1",
                "--set", "snap.fingertip.softLayers=1", "--set",
                "snap.params={\"t0\": 0, \"t1\": 0.02, \"vp\": 0.002, \"t2\": 0.04, \"t3\": 0.08, \"vs\": 0.01}",
                "--set", "budget.maxNewtonIterationsPerSecond=1000");
        assertEquals(0, r.status(), r.toString());
        List<handsim.cards.study.TrialRecord> trials = handsim.cards.study.Study.open(out).trials();
        assertEquals(3, trials.size(), "every trial finished");
        long failed = trials.stream().filter(t -> !t.isComplete()).count();
        assertTrue(failed >= 1 && failed < 3, failed + " trials failed");
        for (var t : trials) {
            assertTrue(t.isComplete() ? t.info().get("newtonIterations") <= 100
                    : t.error().startsWith("past its budget: more than 100 Newton iterations by step "), t.number() + ": " + t.error());
        }
    }
}
