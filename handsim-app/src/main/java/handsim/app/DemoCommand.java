package handsim.app;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Home;
import handsim.evaluation.CatchEvaluation;
import handsim.report.Outputs;
import handsim.report.Plot;
import handsim.report.Stop;
import handsim.scene.SceneSetup;
import handsim.sim.Simulator;
import handsim.task.CatchThrowEpisode;
import handsim.task.EpisodeLimits;
import handsim.task.HeightGoals;
import handsim.task.HeightTask;
import handsim.task.LoopRecord;
import handsim.taskdef.FlipDefinition;
import handsim.taskdef.HeightDefinition;
import handsim.train.ThrowPolicyFile;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code handsim demo}, the main job: endless catch-and-throw of a sphere to varying heights, or,
 * with an object the flip task takes ({@code --object can}, {@code club}), flipping it and
 * catching it over and over with the shipped flip policy ({@link FlipDemo}). With a display it
 * opens the viewer; without one it runs a fixed number of throws headless, prints each, and writes
 * a run folder with a summary and a plot.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = "The main job: the hand catches and throws a sphere to a new random height every loop; with --object can "
                + "or club it flips the object and catches it lying in the hand, over and over, with the shipped flip policy "
                + "(models/policies/flip-<object>.json, the learned controller alone). "
                + "Opens the viewer when there is a display (Esc quits); otherwise (or with --headless) runs --loops throws "
                + "headless and writes summary.json, loops.csv and apex.png (flips: rotation.png) to a run folder (stopped by "
                + "SIGTERM or Ctrl-C, the throws made so far, marked interrupted).")
final class DemoCommand implements Callable<Integer> {

    @Mixin
    EpisodeOptions episodeOptions;

    @Option(names = "--loops", defaultValue = "20", description = "throws to make when headless (default: ${DEFAULT-VALUE})")
    int loops;

    @Option(names = "--heights", paramLabel = "LOW:HIGH",
            description = "range of the random apex goals, m (default: the height task's trained range, configs/tasks/height.json)")
    String heights;

    @Option(names = "--out", paramLabel = "DIR", description = "run folder, new or empty (default: a new "
            + "demo__<object>__<seed>__<time> in --runs)")
    Path out;

    @Option(names = "--runs", paramLabel = "DIR", description = "where the new run folder goes (default: runs/)")
    Path runs;

    @Option(names = "--headless", description = "run headless even when a display is available")
    boolean headless;

    @Option(names = "--export", paramLabel = "FILE", description = "headless: also write the run's animation (FILE.glb, "
            + "FILE.gltf or FILE.bvh; see export)")
    Path export;

    /** What a headless demo writes into its run folder. */
    private static final String[] RUN_FILES = {"summary.json", "loops.csv", "apex.png", "rotation.png"};

    /** The controller the headless run uses. */
    private String controllerShown = "nominal";

    /** The best controller handsim ships for the height task with {@code object}: learned when a policy ships for it. */
    static String bestController(String object) {
        return Files.isRegularFile(shippedPolicy(object)) ? "learned" : "nominal";
    }

    static Path shippedPolicy(String object) {
        return ThrowPolicyFile.shipped(HeightDefinition.NAME, object);
    }

    @Override
    public Integer call() throws Exception {
        if (loops < 1 || loops > 100000) {
            throw new IllegalArgumentException("--loops must be in [1, 100000], got " + loops);
        }
        if (out != null && runs != null) {
            throw new IllegalArgumentException("--out names the run folder, --runs where a new one goes: give one of them");
        }
        if (export != null && !headless && ViewerSession.hasDisplay()) {
            throw new IllegalArgumentException("--export goes with --headless (in the viewer, G records glTF)");
        }
        String object = episodeOptions.object;
        long seed = episodeOptions.seed;
        if (FlipDemo.flips(object)) {
            if (heights != null) {
                throw new IllegalArgumentException("--heights goes with the height demo (a sphere or cuboid), not with a " + object
                        + ", which the demo flips");
            }
            String flipController = FlipDemo.shippedPolicy(object) != null ? "learned" : "nominal";
            if (!headless && ViewerSession.hasDisplay()) {
                return ViewerSession.open("demo", new SceneSetup(FlipDefinition.NAME, object, flipController, seed), null,
                        ControllerOptions.Choice.SHIPPED, 0, null);
            }
            if (!headless) {
                System.out.println("handsim demo: no display (DISPLAY is not set): running " + loops + " throws headless");
            }
            RunExport flipExport = RunExport.to(export);
            new FlipDemo(object, seed, loops).run(out != null ? RunFolders.claimGiven("--out", out, RUN_FILES)
                    : RunFolders.claim(runs, "--runs", "demo", object, seed), flipExport);
            return 0;
        }
        HeightGoals goals = heights != null ? parseHeights(heights) : height().newTask((HeightGoals) null).goals();
        String controller = bestController(object);
        RunExport exported = RunExport.to(export);
        if (!headless && ViewerSession.hasDisplay()) {
            return ViewerSession.open("demo", new SceneSetup(HeightDefinition.NAME, episodeOptions.object, controller, episodeOptions.seed), goals,
                    ControllerOptions.Choice.SHIPPED, 0, null);
        }
        if (!headless) {
            System.out.println("handsim demo: no display (DISPLAY is not set): running " + loops + " throws headless");
        }
        HeightTask task = height().newTask(goals);
        EpisodeLimits limits = Wiring.episodeLimits();
        CatchEvaluation evaluation = new CatchEvaluation(Wiring.controllerConfig(), limits, Wiring.launches(),
                Wiring.object(episodeOptions.object), task, controller.equals("learned")
                        ? ThrowPolicyFile.load(shippedPolicy(episodeOptions.object)).forTask(task, Wiring.object(episodeOptions.object)) : obs -> task.nominalThrow());
        Path dir = out != null ? RunFolders.claimGiven("--out", out, RUN_FILES)
                : RunFolders.claim(runs, "--runs", "demo", episodeOptions.object, episodeOptions.seed);
        System.out.printf("handsim demo: the %s controller%s, goals %.2f-%.2f m%n", controller, controller.equals("learned")
                ? " (" + Home.root().relativize(shippedPolicy(episodeOptions.object)) + ")" : "", goals.low(), goals.high());
        this.controllerShown = controller;
        try {
            run(evaluation, limits, goals, dir, exported);
        } catch (RuntimeException e) { // a diverged world, a demo that gave up: no run folder is left half-written
            RunFolders.release(dir);
            throw e;
        }
        return 0;
    }

    /**
     * The headless demo: throws until --loops, giving up after limits' failed throw-ins in a row;
     * then its run folder, and the animation if {@code exported} is not null.
     */
    private void run(CatchEvaluation evaluation, EpisodeLimits limits, HeightGoals goals, Path dir, RunExport exported)
            throws IOException {
        List<LoopRecord> throwsMade = new ArrayList<>();
        List<Long> throwSeeds = new ArrayList<>();
        int episodes = 0, firstCatchMisses = 0, failedInARow = 0;
        long t0 = System.nanoTime();
        try (Stop.Watch watch = Stop.watch(); Simulator sim = Wiring.simulator(Wiring.model(null), Wiring.simConfig())) {
            for (long s = episodeOptions.seed; throwsMade.size() < loops && !Stop.requested(); s++) {
                if (failedInARow == limits.maxFailedThrowIns()) {
                    throw new RunFailed("gave up after " + failedInARow + " throw-ins in a row that the hand did not catch "
                            + "(seeds " + (s - failedInARow) + "-" + (s - 1) + "; configs/episode.json maxFailedThrowIns), "
                            + throwsMade.size() + " of " + loops + " throws made: is the " + episodeOptions.object + " one a hand can catch?");
                }
                episodes++;
                boolean caughtIn = false;
                CatchThrowEpisode episode = evaluation.start(sim, s);
                while (episode.status() == CatchThrowEpisode.Status.RUNNING && throwsMade.size() < loops && !Stop.requested()) {
                    LoopRecord r = evaluation.tick(episode, s); // a divergence names the seed and loop
                    if (exported != null) {
                        exported.afterTick(sim);
                    }
                    if (r == null) {
                        continue;
                    }
                    if (r.index() == 0) {
                        caughtIn = r.caught();
                        firstCatchMisses += r.caught() ? 0 : 1;
                        System.out.printf("episode %d: object thrown in, %s%n", s, r.caught() ? "caught" : "missed");
                        continue;
                    }
                    throwsMade.add(r);
                    throwSeeds.add(s);
                    System.out.printf("throw %3d/%d: goal %.3f m  apex %.3f m  error %+.3f m  %s%n", throwsMade.size(), loops,
                            r.targetHeight(), r.apexHeight(), r.apexHeight() - r.targetHeight(), r.caught() ? "caught" : "DROPPED");
                }
                failedInARow = caughtIn ? 0 : failedInARow + 1;
            }
        }
        double wall = (System.nanoTime() - t0) / 1e9;
        writeRun(dir, throwsMade, throwSeeds, episodes, firstCatchMisses, goals, wall);
        Stop.check("the " + throwsMade.size() + " throws made are in " + dir.resolve("summary.json") + ", marked interrupted");
        if (exported != null) {
            exported.write("handsim demo: height task, " + episodeOptions.object + ", " + controllerShown + " controller, seed " + episodeOptions.seed);
        }
    }

    private void writeRun(Path dir, List<LoopRecord> loopsMade, List<Long> seeds, int episodes, int firstCatchMisses,
            HeightGoals goals, double wall) throws IOException {
        int n = loopsMade.size();
        double[] index = new double[n], goal = new double[n], apex = new double[n];
        StringBuilder csv = new StringBuilder("throw,episode_seed,goal_m,apex_m,error_m,caught\n");
        int caught = 0;
        double absError = 0, maxAbsError = 0;
        for (int i = 0; i < n; i++) {
            LoopRecord r = loopsMade.get(i);
            index[i] = i + 1;
            goal[i] = r.targetHeight();
            apex[i] = r.apexHeight();
            double err = r.apexHeight() - r.targetHeight();
            absError += Math.abs(err);
            maxAbsError = Math.max(maxAbsError, Math.abs(err));
            caught += r.caught() ? 1 : 0;
            csv.append(String.format(Locale.ROOT, "%d,%d,%.4f,%.4f,%.4f,%s%n", i + 1, seeds.get(i), goal[i], apex[i], err, r.caught()));
        }
        ObjectNode summary = JsonNodeFactory.instance.objectNode();
        summary.put("command", "demo");
        summary.put("controller", controllerShown);
        summary.put("object", episodeOptions.object);
        summary.put("seed", episodeOptions.seed);
        summary.put("heights_low_m", goals.low());
        summary.put("heights_high_m", goals.high());
        summary.put("throws", n);
        summary.put("catches", caught);
        summary.put("drops", n - caught);
        summary.put("episodes", episodes);
        summary.put("first_catch_misses", firstCatchMisses);
        summary.put("height_error_abs_mean_m", n > 0 ? absError / n : Double.NaN);
        summary.put("height_error_abs_max_m", maxAbsError);
        summary.put("wall_s", wall);
        if (Stop.requested()) {
            summary.put("interrupted", Stop.signal() + " after " + n + " of " + loops + " throws");
        }
        Outputs.writeJson(dir.resolve("summary.json"), summary);
        Outputs.writeString(dir.resolve("loops.csv"), csv.toString());
        new Plot("Apex height per throw (" + episodeOptions.object + ", " + controllerShown + " controller)", "throw", "height (m)")
                .add("goal", index, goal, Plot.RED, Plot.Style.POINTS)
                .add("apex reached", index, apex, Plot.BLUE, Plot.Style.LINE_POINTS)
                .writePng(dir.resolve("apex.png"));
        System.out.printf(Locale.ROOT, "%d throws: %d caught, %d dropped (%d episodes); mean |apex - goal| %.3f m; %.0f s%n",
                n, caught, n - caught, episodes, n > 0 ? absError / n : Double.NaN, wall);
        System.out.println("wrote " + dir.resolve("summary.json") + ", loops.csv, apex.png");
    }

    /** The shipped height task's definition. */
    private static HeightDefinition height() {
        return Wiring.shipped().height();
    }

    /** {@code LOW:HIGH} in metres, for {@code --heights}. */
    static HeightGoals parseHeights(String text) {
        String[] parts = text.split(":");
        HeightTask.Config height = height().config();
        try {
            if (parts.length == 2 && height.allowsGoal(Double.parseDouble(parts[0])) && height.allowsGoal(Double.parseDouble(parts[1]))) {
                return new HeightGoals(Double.parseDouble(parts[0]), Double.parseDouble(parts[1]));
            }
        } catch (IllegalArgumentException e) {
            // not numbers, or LOW above HIGH: the message below
        }
        throw new IllegalArgumentException("--heights must be LOW:HIGH in metres with " + height.lowestGoal() + " < LOW <= HIGH < "
                + height.highestGoal() + ", got \"" + text + "\"");
    }
}
