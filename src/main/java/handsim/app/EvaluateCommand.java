package handsim.app;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.CatchStyle;
import handsim.control.ControllerConfig;
import handsim.control.ThrowPolicy;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.report.EpisodeJournal;
import handsim.report.Outputs;
import handsim.report.Plot;
import handsim.rollout.LocalRollouts;
import handsim.rollout.RolloutTask;
import handsim.rollout.Rollouts;
import handsim.sim.ObjectSpec;
import handsim.sim.SimConfig;
import handsim.task.BoxTask;
import handsim.task.BoxTests;
import handsim.task.CatchEvaluation;
import handsim.task.ThrowPlanner;
import handsim.task.EpisodeResult;
import handsim.task.FlipTask;
import handsim.task.HeightErrors;
import handsim.task.HeightGoals;
import handsim.task.LaunchSensitivity;
import handsim.task.LoopProgress;
import handsim.task.LoopRecord;
import handsim.task.StateVector;
import handsim.task.Tasks;
import handsim.task.ThrowTask;
import handsim.train.ThrowPolicyFile;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import handsim.sim.Simulator;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.function.Function;
import java.util.stream.Collectors;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code handsim evaluate}: seeded catch-and-throw episodes of a task with the nominal or a
 * learned controller, with the per-loop figures and the paper's: the height errors and their
 * histogram (Fig. 5), the box tests and their success map (Fig. 8).
 */
@Command(name = "evaluate", mixinStandardHelpOptions = true,
        description = "Run seeded catch-and-throw episodes of a task: an object is thrown toward the hand (configs/launch.json), "
                + "then the arm catches and throws. height: --episodes episodes of up to --loops throws, a new random target "
                + "apex every throw (or --throw-height, or --goals); summary with the height errors and their histogram. "
                + "box: --tests box positions, each a test that succeeds after 6 hit-and-catch loops in a row; summary "
                + "with the success rate by distance from the region's centre and a success map. flip: --episodes episodes "
                + "that run until a throw fails to flip or is dropped (at most --loops); summary with the consecutive "
                + "flip-and-catch loops.")
final class EvaluateCommand implements Callable<Integer> {

    /** Hit-and-catch loops in a row that make a box test a success (paper sec. 4.3). */
    static final int BOX_LOOPS_REQUIRED = 6;
    /** Distance bands of the box report: quarters of the region's radius. */
    static final int BOX_BANDS = 4;

    @Option(names = "--task", defaultValue = "height", description = "height, box or flip (default: ${DEFAULT-VALUE})")
    String task;

    @Option(names = "--controller", defaultValue = "nominal", description = "nominal or learned (default: ${DEFAULT-VALUE})")
    String controller;

    @Option(names = "--policy", paramLabel = "FILE",
            description = "the learned controller's policy (default: the shipped models/policies/<task>-<object>.json)")
    Path policy;

    @Option(names = "--object", defaultValue = "sphere", description = "sphere, can, cuboid or club (configs/objects)")
    String object;

    /** Throws a height episode attempts after the first catch unless --loops says otherwise. */
    static final int HEIGHT_DEFAULT_LOOPS = 10;
    /** The most flip-and-catch loops a flip episode runs to unless --loops says otherwise: twice the can's goal of a mean of 50 (docs/results.md). */
    static final int FLIP_DEFAULT_LOOPS = 100;

    @Option(names = "--loops", paramLabel = "N", description = "height: throws to attempt per episode after the first catch (default "
            + HEIGHT_DEFAULT_LOOPS + "); "
            + "flip: the most flip-and-catch loops an episode runs to (default " + FLIP_DEFAULT_LOOPS + ")")
    Integer loopsOption;

    /** --loops, or the task's default. */
    int loops;

    @Option(names = "--episodes", defaultValue = "1", description = "height: episodes, seeded --seed, --seed+1, ...")
    int episodes;

    @Option(names = "--tests", defaultValue = "538", description = "box: box positions to test (default: ${DEFAULT-VALUE}, the paper's)")
    int tests;

    @Option(names = "--seed", defaultValue = "1", description = "seed of the first episode or test")
    long seed;

    @Option(names = "--throw-height", paramLabel = "H",
            description = "height: every throw aims at H m (default: a random target per throw from configs/tasks/height.json)")
    Double throwHeight;

    @Option(names = "--goals", paramLabel = "FILE",
            description = "goals to use instead of seeded ones: {\"heights\": [h, ...]} (one per throw, in turn) or "
                    + "{\"boxes\": [[x, y, z], ...]} (one per test, m, world)")
    Path goals;

    @Option(names = "--workers", paramLabel = "N",
            description = "episodes run in parallel, each worker with its own engine (default: all local cores); "
                    + "results do not depend on it")
    Integer workers;

    /** A planned flip episode prints a line every this many loops in a row. */
    private static final int PLANNED_PROGRESS_EVERY = 10;

    /** Throws a sensitivity run (--copies) makes per copy unless --loops says otherwise. */
    static final int SENSITIVITY_DEFAULT_LOOPS = 5;

    @Option(names = "--copies", paramLabel = "N",
            description = "height, flip: instead of the summary, run every episode N times, copy 0 as seeded and the others with "
                    + "the launch velocity nudged by --nudge in a random direction, for --loops throws (default "
                    + SENSITIVITY_DEFAULT_LOOPS + ") whether they succeed or not, and report how far each throw's apex and flight "
                    + "rotation spread across the copies")
    Integer copies;

    @Option(names = "--nudge", paramLabel = "V", defaultValue = "1e-9",
            description = "the launch velocity nudge of --copies (m/s, default: ${DEFAULT-VALUE})")
    double nudge;

    @Option(names = "--plan", description = "flip: choose every throw by trying the policy's throw and variations of it in a twin "
            + "world first (handsim.task.ThrowPlanner, settings in configs/planner.json); the hand then makes the best")
    boolean plan;

    @Option(names = "--json", paramLabel = "FILE", description = "write the summary as JSON, with its provenance (commit, "
            + "command line, SHA-256 of every config, model and policy file read); while the run goes, each finished episode is "
            + "kept in FILE.episodes.jsonl, and the same command run again after a kill runs only the episodes not yet finished")
    Path json;

    @Spec
    CommandSpec spec;

    /** The finished episodes of this run and of an earlier, interrupted run of the same command (with --json), or null. */
    private EpisodeJournal journal;

    @Option(names = "--csv", paramLabel = "FILE", description = "write one row per loop (height, flip) or test (box) as CSV")
    Path csv;

    @Option(names = "--plot", paramLabel = "FILE",
            description = "the histogram (height), success map (box) or loops per episode (flip, with the throws by flight rotation "
                    + "beside it as NAME-rotation.png) PNG, or with --copies the spread by throw (default: next to --json, same name "
                    + "with .png)")
    Path plot;

    @Option(names = "--export", paramLabel = "FILE",
            description = "with --episodes 1 (box: --tests 1): also write the episode's animation (FILE.glb, FILE.gltf or FILE.bvh; see export)")
    Path export;

    /** The episode's animation export, or null. */
    private RunExport exported;

    @Override
    public Integer call() throws Exception {
        loops = loopsOption != null ? loopsOption
                : copies != null ? SENSITIVITY_DEFAULT_LOOPS : task.equals("flip") ? FLIP_DEFAULT_LOOPS : HEIGHT_DEFAULT_LOOPS;
        validate();
        if (json != null) {
            journal = EpisodeJournal.open(json.resolveSibling(json.getFileName() + ".episodes.jsonl"), signature());
            if (journal.finished() > 0) {
                System.out.printf("resuming: %d finished episodes read from %s%s%n", journal.finished(), journal.file(),
                        journal.droppedLines() > 0 ? " (" + journal.droppedLines() + " line cut short by a kill dropped)" : "");
            }
        }
        HandModel model = Runtime.model(null);
        SimConfig simConfig = Runtime.simConfig();
        Function<ThrowTask, ThrowPolicy> policies = throwPolicies();
        long t0 = System.nanoTime();
        ObjectNode out = JsonNodeFactory.instance.objectNode();
        out.put("task", task);
        out.put("controller", controller);
        out.put("planned", plan);
        if (policy != null || controller.equals("learned")) {
            out.put("policy", policyFile().toString());
        }
        out.put("object", object);
        out.put("seed", seed);
        out.put("workers", workers);
        try (Rollouts rollouts = Runtime.rollouts(model, simConfig, workers)) {
            if (copies != null) {
                evaluateSensitivity(rollouts, policies, out);
            } else if (task.equals("box")) {
                evaluateBox(rollouts, policies, out);
            } else if (task.equals("flip")) {
                evaluateFlip(rollouts, policies, out);
            } else {
                evaluateHeight(rollouts, policies, out);
            }
        }
        out.put("wall_s", (System.nanoTime() - t0) / 1e9);
        if (exported != null) {
            exported.write("handsim evaluate: " + task + " task, " + object + ", " + controllerLabel() + " controller, seed " + seed);
        }
        if (journal != null) {
            out.put("episodes_resumed", journal.finished() - newlyFinished);
        }
        out.set("provenance", Provenance.of(spec.commandLine().getParseResult().originalArgs()));
        if (json != null) {
            Outputs.writeJson(json, out);
            System.out.println("wrote " + json);
            journal.delete();
        }
        return 0;
    }

    /** Episodes this run finished itself (the journal's others were read back). */
    private int newlyFinished;

    /**
     * What makes this run's episodes what they are: the options that change a result (not
     * --workers, --episodes or --tests: more episodes of the same run keep the first ones) and
     * the SHA-256 of every file under configs/ and models/ and of --policy and --goals.
     */
    private com.fasterxml.jackson.databind.node.ObjectNode signature() throws IOException {
        ObjectNode s = JsonNodeFactory.instance.objectNode();
        s.put("task", task).put("controller", controller).put("plan", plan).put("object", object).put("loops", loops).put("seed", seed);
        s.put("policy", controller.equals("learned") ? policyFile().toAbsolutePath().normalize().toString() : null);
        s.put("throw_height", throwHeight);
        s.put("copies", copies);
        s.put("nudge", copies != null ? nudge : null);
        ObjectNode files = s.putObject("files");
        java.util.SortedMap<String, String> hashes = new java.util.TreeMap<>();
        for (String dir : List.of("configs", "models")) {
            try (var walk = Files.walk(Home.resolve(dir))) {
                for (Path f : walk.filter(Files::isRegularFile).toList()) {
                    hashes.put(Home.root().relativize(f).toString(), handsim.config.ReadLog.sha256(Files.readAllBytes(f)));
                }
            }
        }
        for (Path f : java.util.Arrays.asList(controller.equals("learned") ? policyFile() : null, goals)) {
            if (f != null && Files.isRegularFile(f)) {
                hashes.put(f.toAbsolutePath().normalize().toString(), handsim.config.ReadLog.sha256(Files.readAllBytes(f)));
            }
        }
        hashes.forEach(files::put);
        return s;
    }

    /**
     * {@code task} that reads an episode back from the journal when an interrupted run of the same command finished it,
     * and otherwise runs it and journals its result at once (without --json, {@code task} itself).
     */
    private <R> RolloutTask<R> resumable(RolloutTask<R> task, Function<R, JsonNode> write, Function<JsonNode, R> read) {
        if (journal == null) {
            return task;
        }
        return sim -> {
            RolloutTask.Rollout<R> rollout = task.prepare(sim);
            return i -> {
                java.util.Optional<JsonNode> earlier = journal.result(i);
                if (earlier.isPresent()) {
                    return read.apply(earlier.get());
                }
                R result = rollout.run(i);
                journal.append(i, write.apply(result));
                synchronized (this) {
                    newlyFinished++;
                }
                return result;
            };
        };
    }

    private void validate() {
        if (!List.of("height", "box", "flip").contains(task)) {
            throw new IllegalArgumentException("--task must be height, box or flip, got " + task);
        }
        if (!List.of("nominal", "learned").contains(controller)) {
            throw new IllegalArgumentException("--controller must be nominal or learned, got " + controller);
        }
        if (policy != null && !controller.equals("learned")) {
            throw new IllegalArgumentException("--policy goes with --controller learned");
        }
        if (loops < 0 || loops > 100000) {
            throw new IllegalArgumentException("--loops must be in [0, 100000], got " + loops);
        }
        if (episodes < 1 || episodes > 100000) {
            throw new IllegalArgumentException("--episodes must be in [1, 100000], got " + episodes);
        }
        if (tests < 1 || tests > 100000) {
            throw new IllegalArgumentException("--tests must be in [1, 100000], got " + tests);
        }
        if (throwHeight != null && !(throwHeight > HeightGoals.LOWEST && throwHeight < HeightGoals.HIGHEST)) {
            throw new IllegalArgumentException("--throw-height must be in (" + HeightGoals.LOWEST + ", " + HeightGoals.HIGHEST
                    + ") m, got " + throwHeight);
        }
        if (throwHeight != null && (goals != null || task.equals("box"))) {
            throw new IllegalArgumentException("--throw-height goes with the height task and without --goals");
        }
        if (copies != null && (copies < 2 || copies > 1000 || task.equals("box"))) {
            throw new IllegalArgumentException("--copies must be in [2, 1000] and goes with the height or flip task, got " + copies
                    + " with " + task);
        }
        if (copies != null && csv != null) {
            throw new IllegalArgumentException("--csv goes without --copies (a sensitivity run writes its figures with --json)");
        }
        if (plan && (!task.equals("flip") || copies != null)) {
            throw new IllegalArgumentException("--plan goes with the flip task and without --copies");
        }
        if (!(nudge > 0 && nudge <= 1)) {
            throw new IllegalArgumentException("--nudge must be in (0, 1] m/s, got " + nudge);
        }
        if (goals != null && !Files.isRegularFile(goals)) {
            throw new IllegalArgumentException("--goals: no file " + goals);
        }
        if (workers == null) {
            workers = LocalRollouts.localCores();
        }
        if (workers < 1 || workers > 256) {
            throw new IllegalArgumentException("--workers must be in [1, 256], got " + workers);
        }
        if (export != null && (episodes != 1 || copies != null || task.equals("box") && tests != 1)) {
            throw new IllegalArgumentException("--export goes with one episode: --episodes 1 (box: --tests 1), without --copies");
        }
        exported = RunExport.to(export);
        if (plot == null && json != null) {
            String name = json.getFileName().toString();
            plot = json.resolveSibling((name.endsWith(".json") ? name.substring(0, name.length() - 5) : name) + ".png");
        }
        new OutputPaths().file("--json", json).file("--csv", csv).file("--plot", plot).check();
    }

    /** A progress line with the time left every configs/episode.json progressEveryLoops loops of an episode. */
    private CatchEvaluation.LoopListener longEpisodeProgress() {
        return new LoopProgress(System.out, Runtime.episodeLimits().progressEveryLoops(), loops);
    }

    /** The controller as printed and in the charts' titles: with --plan, "learned + planner". */
    private String controllerLabel() {
        return plan ? controller + " + planner" : controller;
    }

    /** The policy file of the learned controller: --policy, or the shipped one for the task and object. */
    private Path policyFile() {
        return policy != null ? policy : ThrowPolicyFile.shipped(task, object);
    }

    /** How each worker's task gets its throw policy: the task's nominal throw, or the learned policy. */
    private Function<ThrowTask, ThrowPolicy> throwPolicies() {
        if (controller.equals("nominal")) {
            return t -> obs -> t.nominalThrow();
        }
        Path file = policyFile();
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException(policy != null ? "--policy: no file " + file
                    : "no shipped policy for the " + task + " task with a " + object + " (" + Home.root().relativize(file)
                            + "): train one (scripts/handsim train) and give it with --policy");
        }
        ThrowPolicyFile loaded = ThrowPolicyFile.load(file);
        ObjectSpec spec = Runtime.object(object);
        StateVector.Hand hand = StateVector.Hand.of(Runtime.model(null));
        loaded.forTask(Runtime.tasks().create(task, object), spec, hand); // a policy for another task or object fails here
        return t -> loaded.forTask(t, spec, hand);
    }

    /** A worker's evaluation: its own task (goals are per-episode state) and throw policy. */
    private CatchEvaluation evaluation(ThrowTask t, Function<ThrowTask, ThrowPolicy> policies, ControllerConfig cc,
            ObjectSpec spec) {
        return new CatchEvaluation(cc, Runtime.episodeLimits(), Runtime.launches(), spec, t, policies.apply(t)).watchedBy(exported);
    }

    /** The heights of --goals, or null. */
    private double[] heightList() {
        return goals != null ? readGoals(goals, "heights", 1).stream().mapToDouble(g -> g[0]).toArray() : null;
    }

    /** A worker's height goals: --goals in turn, --throw-height, or (null) seeded random ones. */
    private HeightGoals heightGoals(double[] heightList) {
        return heightList != null ? HeightGoals.sequence(heightList) : throwHeight != null ? HeightGoals.fixed(throwHeight) : null;
    }

    // ---- height ---------------------------------------------------------------------------

    private void evaluateHeight(Rollouts rollouts, Function<ThrowTask, ThrowPolicy> policies, ObjectNode out) throws Exception {
        ControllerConfig cc = Runtime.controllerConfig();
        ObjectSpec spec = Runtime.object(object);
        double[] heightList = heightList();
        Tasks tasks = Runtime.tasks();
        StringBuilder rows = new StringBuilder("episode_seed,loop,caught,apex_m,target_apex_m,landing_x,landing_y,landing_z,"
                + "max_penetration_mm,max_limit_excess_deg,peak_torque_ratio,duration_s\n");
        // episode i has seed --seed + i on whichever worker runs it; printed in seed order
        List<EpisodeResult> results = rollouts.run(episodes, resumable(sim -> {
            CatchEvaluation evaluation = evaluation(tasks.height(heightGoals(heightList)), policies, cc, spec);
            return i -> evaluation.run(sim, seed + i, loops, longEpisodeProgress());
        }, ResultJson::episode, ResultJson::episode), (i, r) -> {
            for (LoopRecord loop : r.loops()) {
                System.out.printf(Locale.ROOT, "episode %d loop %3d: %-7s apex %s%s  penetration %.1f mm  limit excess %.2f deg"
                        + "  torque %.2f%n", r.seed(), loop.index(), loop.caught() ? "caught" : "DROPPED",
                        Double.isNaN(loop.apexHeight()) ? "  -   " : String.format(Locale.ROOT, "%.3f m", loop.apexHeight()),
                        Double.isNaN(loop.targetHeight()) ? "" : String.format(Locale.ROOT, " (goal %.3f, %+.3f)",
                                loop.targetHeight(), loop.apexHeight() - loop.targetHeight()),
                        loop.maxPenetration() * 1e3, Math.toDegrees(loop.maxLimitExcess()), loop.peakTorqueRatio());
                rows.append(csvRow(r.seed(), loop));
            }
            System.out.printf("episode %d: first catch %s, %d loops completed, %d attempted (%s)%n", r.seed(),
                    r.firstCatch() ? "yes" : "no", r.loopsCompleted(), r.loopsAttempted(), r.status());
        });
        out.put("episodes_requested", episodes);
        out.put("loops_per_episode", loops);
        if (throwHeight != null) {
            out.put("throw_height_m", throwHeight);
        }
        out.setAll(summarize(results, 0));
        out.remove("wall_s");
        HeightErrors errors = HeightErrors.of(results.stream().flatMap(r -> r.loops().stream()).toList());
        out.put("throws", errors.count());
        out.put("height_error_mean", errors.mean());
        out.put("height_error_abs_mean", errors.absMean());
        out.put("height_error_p95", errors.absP95());
        out.put("within_0_1_m", errors.within(0.1));
        ArrayNode eps = out.putArray("episodes");
        for (EpisodeResult r : results) {
            ObjectNode o = eps.addObject();
            o.put("seed", r.seed());
            o.put("first_catch", r.firstCatch());
            o.put("loops_attempted", r.loopsAttempted());
            o.put("loops_completed", r.loopsCompleted());
            o.put("drops", r.drops());
            o.put("end", r.status().name().toLowerCase(Locale.ROOT));
            o.put("max_limit_excess_deg", Math.toDegrees(r.maxLimitExcess()));
            o.put("max_penetration_mm", r.maxPenetration() * 1e3);
            o.put("peak_torque_ratio", r.peakTorqueRatio());
        }
        System.out.printf(Locale.ROOT, "%s, %s controller, %d episodes: first catch %.0f %%, loops completed %d (mean %.2f), "
                + "drops %d, loops out of time %d; %d throws: height error mean %+.4f m, |error| mean %.4f m, p95 %.4f m, within 0.1 m %.1f %%; "
                + "max limit excess %.2f deg, max penetration %.1f mm, peak torque ratio %.2f%n", object, controller, episodes,
                100 * out.get("first_catch_rate").asDouble(), out.get("loops_completed").asInt(),
                out.get("loops_completed_mean").asDouble(), out.get("drops").asInt(), out.get("time_outs").asInt(), errors.count(), errors.mean(),
                errors.absMean(), errors.absP95(), 100 * errors.within(0.1), out.get("max_limit_excess_deg").asDouble(),
                out.get("max_penetration_mm").asDouble(), out.get("peak_torque_ratio").asDouble());
        writeCsv(rows);
        if (plot != null && errors.count() > 0) {
            errors.writeHistogram(plot, String.format(Locale.ROOT, "Height error, %s controller, %s (%d throws)", controller,
                    object, errors.count()), 0.01);
            System.out.println("wrote " + plot);
        }
    }

    private static String csvRow(long seed, LoopRecord r) {
        return String.format(Locale.ROOT, "%d,%d,%s,%s,%s,%s,%.3f,%.3f,%.3f,%.3f%n", seed, r.index(), r.caught(),
                csvNumber(r.apexHeight()), csvNumber(r.targetHeight()), csvPoint(r.landing()), r.maxPenetration() * 1e3,
                Math.toDegrees(r.maxLimitExcess()), r.peakTorqueRatio(), r.duration());
    }

    /** Writes the --csv file, if one was asked for. */
    private void writeCsv(CharSequence rows) throws IOException {
        if (csv != null) {
            Outputs.writeString(csv, rows.toString());
            System.out.println("wrote " + csv);
        }
    }

    private static String csvNumber(double v) {
        return Double.isNaN(v) ? "" : String.format(Locale.ROOT, "%.4f", v);
    }

    private static String csvPoint(Vec3 p) {
        return p == null ? ",," : csvNumber(p.x()) + "," + csvNumber(p.y()) + "," + csvNumber(p.z());
    }

    /** Aggregate figures: the fields plus natural-motion figures (limits, penetration, torque). */
    static ObjectNode summarize(List<EpisodeResult> results, double wallSeconds) {
        ObjectNode s = JsonNodeFactory.instance.objectNode();
        int n = results.size();
        s.put("episodes_run", n);
        s.put("loops_attempted", results.stream().mapToInt(EpisodeResult::loopsAttempted).sum());
        s.put("loops_completed", results.stream().mapToInt(EpisodeResult::loopsCompleted).sum());
        s.put("drops", results.stream().mapToInt(EpisodeResult::drops).sum());
        s.put("time_outs", results.stream().mapToInt(EpisodeResult::timeOuts).sum());
        s.put("first_catch", results.stream().allMatch(EpisodeResult::firstCatch));
        s.put("first_catches", results.stream().filter(EpisodeResult::firstCatch).count());
        s.put("first_catch_rate", results.stream().filter(EpisodeResult::firstCatch).count() / (double) n);
        s.put("loops_completed_mean", results.stream().mapToInt(EpisodeResult::loopsCompleted).average().orElse(0));
        s.put("loops_completed_min", results.stream().mapToInt(EpisodeResult::loopsCompleted).min().orElse(0));
        s.put("loops_completed_max", results.stream().mapToInt(EpisodeResult::loopsCompleted).max().orElse(0));
        s.put("max_limit_excess_deg", Math.toDegrees(results.stream().mapToDouble(EpisodeResult::maxLimitExcess).max().orElse(0)));
        s.put("max_penetration_mm", 1e3 * results.stream().mapToDouble(EpisodeResult::maxPenetration).max().orElse(0));
        s.put("peak_torque_ratio", results.stream().mapToDouble(EpisodeResult::peakTorqueRatio).max().orElse(0));
        s.put("wall_s", wallSeconds);
        return s;
    }

    // ---- box ------------------------------------------------------------------------------

    private void evaluateBox(Rollouts rollouts, Function<ThrowTask, ThrowPolicy> policies, ObjectNode out) throws Exception {
        ControllerConfig cc = Runtime.controllerConfig();
        ObjectSpec spec = Runtime.object(object);
        Tasks tasks = Runtime.tasks();
        BoxTask reference = (BoxTask) tasks.create("box", object);
        List<Vec3> boxes = new ArrayList<>();
        if (goals != null) {
            readGoals(goals, "boxes", 3).forEach(b -> boxes.add(new Vec3(b[0], b[1], b[2])));
        } else {
            for (int i = 0; i < tests; i++) {
                boxes.add(reference.drawCenter(seed + i));
            }
        }
        StringBuilder rows = new StringBuilder("test,seed,box_x,box_y,box_z,distance_m,success,hit_and_catch_in_a_row\n");
        List<BoxTests.Test> results = rollouts.run(boxes.size(), resumable(sim -> {
            BoxTask t = (BoxTask) tasks.create("box", object);
            CatchEvaluation evaluation = evaluation(t, policies, cc, spec);
            return i -> BoxTests.run(evaluation, t, sim, i, seed + i, boxes.get(i), BOX_LOOPS_REQUIRED);
        }, ResultJson::boxTest, ResultJson::boxTest), (i, r) -> {
            System.out.printf(Locale.ROOT, "test %3d: box (%.3f, %.3f, %.3f), %.3f m from the centre: %s (%d in a row)%n",
                    r.index(), r.box().x(), r.box().y(), r.box().z(), r.distance(), r.success() ? "success" : "failure", r.inARow());
            rows.append(String.format(Locale.ROOT, "%d,%d,%.4f,%.4f,%.4f,%.4f,%s,%d%n", r.index(), r.seed(), r.box().x(),
                    r.box().y(), r.box().z(), r.distance(), r.success(), r.inARow()));
        });
        double radius = reference.regionRadius();
        long successes = results.stream().filter(BoxTests.Test::success).count();
        out.put("tests", results.size());
        out.put("successes", successes);
        putRate(out, "success_rate", results);
        out.put("loops_required", BOX_LOOPS_REQUIRED);
        out.put("region_radius_m", radius);
        List<BoxTests.Test> inner = BoxTests.band(results, 0, 0.5 * radius);
        out.put("inner_half_tests", inner.size());
        putRate(out, "inner_half_success_rate", inner);
        ArrayNode bands = out.putArray("by_distance");
        for (int b = 0; b < BOX_BANDS; b++) {
            double lo = radius * b / BOX_BANDS, hi = b == BOX_BANDS - 1 ? Double.POSITIVE_INFINITY : radius * (b + 1) / BOX_BANDS;
            List<BoxTests.Test> in = BoxTests.band(results, lo, hi);
            ObjectNode o = bands.addObject();
            o.put("from_m", lo);
            o.put("to_m", Math.min(hi, radius));
            o.put("tests", in.size());
            putRate(o, "success_rate", in);
        }
        System.out.printf(Locale.ROOT, "box task, %s controller, %s: %d of %d tests succeeded (%s); inner half of the region "
                + "(within %.3f m of its centre): %s of %d%n", controller, object, successes, results.size(),
                percent(results), 0.5 * radius, percent(inner), inner.size());
        writeCsv(rows);
        if (plot != null) {
            BoxTests.writeMap(plot, results, reference.regionCenter(), String.format(Locale.ROOT,
                    "Box tests, %s controller (%d of %d succeeded)", controller, successes, results.size()));
            System.out.println("wrote " + plot);
        }
    }

    /** The planner's settings and its work over all episodes, printed and in the JSON. */
    private static void putPlannerStats(ObjectNode out, ThrowPlanner.Config planning, ThrowPlanner.Stats s) {
        ObjectNode o = out.putObject("planner");
        ArrayNode rounds = o.putArray("rounds");
        planning.rounds().forEach(r -> putStyles(rounds.addObject().put("candidates", r.candidates()).put("spread", r.spread())
                .putArray("catch_styles"), r.catchStyles()));
        o.put("good_alignment", planning.goodAlignment());
        o.put("lookahead", planning.lookahead());
        o.put("lookahead_depth", planning.lookaheadDepth());
        putStyles(o.putArray("catch_styles"), planning.catchStyles());
        putStyles(o.putArray("throw_in_styles"), planning.throwInStyles());
        putStyles(o.putArray("catch_branches"), planning.catchBranches());
        o.put("decisions", s.decisions());
        o.put("tries", s.tries());
        o.put("unsolved", s.unsolved());
        o.put("mispredicted", s.mispredicted());
        o.put("promised", s.promised());
        o.put("restyled_catches", s.restyledCatches());
        o.put("restyled_throw_ins", s.restyledThrowIns());
        o.put("branches", s.branches());
        System.out.printf(Locale.ROOT, "planner: %d throws chosen from %d tries (%.1f per throw); for %d of them no try succeeded; "
                + "%d began with the throw the lookahead had found; %d live loops differed from their try in the twin; "
                + "%d throws and %d throw-ins caught otherwise than the controller's own way; %d catches played again from a throw's end%n",
                s.decisions(), s.tries(), s.decisions() == 0 ? 0.0 : (double) s.tries() / s.decisions(), s.unsolved(),
                s.promised(), s.mispredicted(), s.restyledCatches(), s.restyledThrowIns(), s.branches());
    }

    private static void putStyles(ArrayNode out, List<CatchStyle> styles) {
        styles.forEach(c -> out.addObject().put("plane_shift", c.planeShift()).put("velocity_fraction", c.velocityFraction()));
    }

    /** A success rate in the JSON: null for no tests (NaN is not JSON). */
    private static void putRate(ObjectNode node, String field, List<BoxTests.Test> tests) {
        if (tests.isEmpty()) {
            node.putNull(field);
        } else {
            node.put(field, BoxTests.successRate(tests));
        }
    }

    private static String percent(List<BoxTests.Test> tests) {
        return tests.isEmpty() ? "no tests" : String.format(Locale.ROOT, "%.1f %%", 100 * BoxTests.successRate(tests));
    }

    // ---- flip -----------------------------------------------------------------------------

    /** How a flip episode ended: its last throw dropped, caught standing, caught lying without a flip, or the cap reached. */
    enum FlipEnd {
        DROPPED, CAUGHT_STANDING, NO_FLIP, REACHED_MAX_LOOPS;

        /** The name in the JSON and CSV. */
        String label() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    /**
     * A flip episode's outcome: loops in a row that flipped and were caught properly, the flips
     * those successful throws made, how it ended, and the planner's work in it (with --plan).
     */
    private record FlipRun(long seed, int inARow, int flips, int throwsMade, FlipEnd end, List<LoopRecord> loops,
            ThrowPlanner.Stats planner) {

        /**
         * The episode of {@code made}, the loops up to and including its first failure (or the cap),
         * with what the planner did in it.
         */
        static FlipRun of(long seed, List<LoopRecord> made, ThrowPlanner.Stats planner, FlipTask task, int maxLoops) {
            int inARow = 0, flips = 0;
            for (LoopRecord r : made) {
                if (r.index() > 0 && task.success(r)) {
                    inARow++;
                    flips += task.flips(r);
                }
            }
            LoopRecord last = made.get(made.size() - 1);
            FlipEnd end = inARow >= maxLoops ? FlipEnd.REACHED_MAX_LOOPS
                    : !last.caught() ? FlipEnd.DROPPED
                    : last.index() > 0 && !task.properCatch(last) ? FlipEnd.CAUGHT_STANDING : FlipEnd.NO_FLIP;
            return new FlipRun(seed, inARow, flips, made.size() - 1, end, made, planner);
        }

        /** How the episode ended, for its progress line. */
        String ending(String object) {
            return switch (end) {
                case DROPPED -> "ended in a drop";
                case CAUGHT_STANDING -> String.format(Locale.ROOT, "ended with the %s caught standing %.0f deg out of the palm", object,
                        Math.toDegrees(loops.get(loops.size() - 1).catchTilt()));
                case NO_FLIP -> "ended with a throw that did not flip";
                case REACHED_MAX_LOOPS -> "reached --loops";
            };
        }
    }

    private void evaluateFlip(Rollouts rollouts, Function<ThrowTask, ThrowPolicy> policies, ObjectNode out) throws Exception {
        ControllerConfig cc = Runtime.controllerConfig();
        ObjectSpec spec = Runtime.object(object);
        Tasks tasks = Runtime.tasks();
        FlipTask flipTask = (FlipTask) tasks.create("flip", object); // an object the flip task cannot take fails here
        ThrowPlanner.Config planning = plan ? Runtime.plannerConfig(object) : null;
        List<Simulator> twins = Collections.synchronizedList(new ArrayList<>());
        List<FlipRun> runs;
        try {
            runs = rollouts.run(episodes, resumable(sim -> {
                FlipTask t = (FlipTask) tasks.create("flip", object);
                CatchEvaluation evaluation = evaluation(t, policies, cc, spec);
                if (planning != null) {
                    Simulator twin = Runtime.twinSimulator(sim);
                    twins.add(twin);
                    evaluation = evaluation.planned(planning, twin);
                }
                CatchEvaluation worker = evaluation;
                return i -> {
                    // planned episodes take minutes each (the club's up to an hour): say how far they are
                    CatchEvaluation.LoopListener progress = planning == null ? longEpisodeProgress() : (episodeSeed, loop) -> {
                        if (loop.index() > 0 && loop.index() % PLANNED_PROGRESS_EVERY == 0 && t.success(loop)) {
                            System.out.printf(Locale.ROOT, "episode %d: %d flip-and-catch loops in a row so far%n", episodeSeed, loop.index());
                        }
                    };
                    List<LoopRecord> made = worker.runWhileSuccessful(sim, seed + i, loops, progress);
                    return FlipRun.of(seed + i, made, worker.episodePlannerStats(), flipTask, loops);
                };
            }, r -> {
                ObjectNode o = JsonNodeFactory.instance.objectNode().put("seed", r.seed());
                o.set("loops", ResultJson.loops(r.loops()));
                o.set("planner", ResultJson.plannerStats(r.planner()));
                return o;
            }, o -> FlipRun.of(o.get("seed").asLong(), ResultJson.loops(o.get("loops")), ResultJson.plannerStats(o.get("planner")),
                    flipTask, loops)), (i, r) -> System.out.printf(Locale.ROOT,
                    "episode %d: %d flip-and-catch loops in a row, %d flips in %d throws, %s%n", r.seed(), r.inARow(), r.flips(),
                    r.throwsMade(), r.ending(object)));
        } finally {
            twins.forEach(Simulator::close);
        }
        if (planning != null) {
            putPlannerStats(out, planning, runs.stream().map(FlipRun::planner).reduce(ThrowPlanner.Stats.NONE, ThrowPlanner.Stats::plus));
        }
        if (csv != null) {
            StringBuilder rows = new StringBuilder("seed,loop,caught,catch_tilt_deg,flips,flight_rotation_deg,release_spin_rad_s,arrival_tilt_deg,apex_m,"
                    + "catch_x,catch_y,catch_z,landing_x,landing_y,landing_z,reward,failure\n");
            for (FlipRun r : runs) {
                for (LoopRecord loop : r.loops()) {
                    rows.append(String.format(Locale.ROOT, "%d,%d,%s,%s,%d,%s,%s,%s,%s,%s,%s,%s,%s%n", r.seed(), loop.index(), loop.caught(),
                            csvNumber(Math.toDegrees(loop.catchTilt())), flipTask.flips(loop), csvNumber(Math.toDegrees(loop.flightRotation())),
                            csvNumber(loop.releaseSpin()), csvNumber(Math.toDegrees(loop.arrivalTilt())), csvNumber(loop.apexHeight()),
                            csvPoint(loop.catchPoint()), csvPoint(loop.landing()),
                            loop.index() == 0 ? "" : csvNumber(flipTask.reward(loop)),
                            loop.index() == 0 ? "" : flipTask.failure(loop).map(FlipTask.Failure::label).orElse("")));
                }
            }
            writeCsv(rows);
        }
        double mean = runs.stream().mapToInt(FlipRun::inARow).average().orElse(0);
        out.put("episodes_run", runs.size());
        out.put("max_loops", loops);
        out.put("loops_completed", runs.stream().mapToInt(FlipRun::inARow).sum());
        out.put("loops_completed_mean", mean);
        out.put("loops_completed_min", runs.stream().mapToInt(FlipRun::inARow).min().orElse(0));
        out.put("loops_completed_max", runs.stream().mapToInt(FlipRun::inARow).max().orElse(0));
        out.put("flips", runs.stream().mapToInt(FlipRun::flips).sum());
        out.put("throws", runs.stream().mapToInt(FlipRun::throwsMade).sum());
        ObjectNode endings = out.putObject("endings");
        for (FlipEnd end : FlipEnd.values()) {
            endings.put(end.label(), runs.stream().filter(r -> r.end() == end).count());
        }
        List<LoopRecord> allLoops = runs.stream().flatMap(r -> r.loops().stream()).toList();
        FlipTask.ThrowTally tally = flipTask.tally(allLoops);
        out.put("method", plan ? "planner-assisted" : "paper's method");
        ObjectNode perThrow = out.putObject("per_throw");
        perThrow.put("throws", tally.throwsMade());
        perThrow.put("successes", tally.successes());
        putFinite(perThrow, "success_rate", tally.successRate());
        ObjectNode failures = perThrow.putObject("failures");
        for (FlipTask.Failure f : FlipTask.Failure.values()) {
            failures.put(f.label(), tally.failures().get(f));
        }
        List<FlipTask.RotationBin> bins = flipTask.byFlightRotation(allLoops);
        ArrayNode byRotation = out.putArray("throws_by_flight_rotation");
        for (FlipTask.RotationBin b : bins) {
            putBin(byRotation, b.from(), b.to(), b.throwsMade(), b.successes());
        }
        List<FlipTask.ArrivalBin> arrivals = flipTask.byArrivalTilt(allLoops);
        ArrayNode byArrival = out.putArray("throws_by_arrival_tilt");
        for (FlipTask.ArrivalBin b : arrivals) {
            putBin(byArrival, b.from(), b.to(), b.throwsMade(), b.successes()).put("drops", b.drops()).put("standing", b.standing());
        }
        ArrayNode eps = out.putArray("episodes");
        for (FlipRun r : runs) {
            ObjectNode o = eps.addObject();
            o.put("seed", r.seed());
            o.put("loops_completed", r.inARow());
            o.put("flips", r.flips());
            o.put("throws", r.throwsMade());
            o.put("end", r.end().label());
        }
        System.out.printf(Locale.ROOT, "flip task, %s controller, %s, %d episodes: flip-and-catch loops in a row mean %.2f "
                + "(min %d, max %d, at most %d); %d flips by the successful throws, %d throws; ended by %d drops, %d catches not lying in the hand, "
                + "%d throws that did not flip%n", controllerLabel(), object, runs.size(), mean, out.get("loops_completed_min").asInt(),
                out.get("loops_completed_max").asInt(), loops, out.get("flips").asInt(), out.get("throws").asInt(),
                endings.get("dropped").asInt(), endings.get("caught_standing").asInt(), endings.get("no_flip").asInt());
        System.out.printf(Locale.ROOT, "per throw (%s): %d of %d throws succeed (%.1f %%); failed: %d arrived end-first, %d dropped, "
                + "%d caught standing, %d did not flip%n", plan ? "planner-assisted" : "paper's method", tally.successes(),
                tally.throwsMade(), 100 * tally.successRate(), tally.failures().get(FlipTask.Failure.ARRIVED_END_FIRST),
                tally.failures().get(FlipTask.Failure.DROPPED), tally.failures().get(FlipTask.Failure.CAUGHT_STANDING),
                tally.failures().get(FlipTask.Failure.NO_FLIP));
        System.out.println("by the long axis's tilt out of the horizontal when the " + object + " came back to the hand: "
                + arrivals.stream().map(b -> String.format(Locale.ROOT, "%.0f-%.0f deg %d (%d ok, %d dropped, %d standing)",
                        Math.toDegrees(b.from()), Math.toDegrees(b.to()), b.throwsMade(), b.successes(), b.drops(), b.standing()))
                        .collect(Collectors.joining("; ")));
        if (plot != null) {
            double[] x = new double[runs.size()], y = new double[runs.size()];
            for (int i = 0; i < x.length; i++) {
                x[i] = runs.get(i).seed();
                y[i] = runs.get(i).inARow();
            }
            new Plot(String.format(Locale.ROOT, "Flip-and-catch loops in a row, %s controller, %s (mean %.2f)",
                    controllerLabel(), object, mean), "episode seed", "loops").add("loops in a row", x, y, Plot.BLUE,
                    Plot.Style.BARS).writePng(plot);
            System.out.println("wrote " + plot);
            Path rotationPlot = besidePlot("-rotation");
            plotByRotation(bins, rotationPlot);
            System.out.println("wrote " + rotationPlot);
            Path arrivalPlot = besidePlot("-arrival");
            plotByArrival(arrivals, arrivalPlot);
            System.out.println("wrote " + arrivalPlot);
        }
    }

    /** Appends a bin of throws between two angles (rad, written in degrees) to a JSON array; returns it for more fields. */
    private static ObjectNode putBin(ArrayNode array, double from, double to, int throwsMade, int successes) {
        ObjectNode o = array.addObject();
        o.put("from_deg", roundedDegrees(from));
        o.put("to_deg", roundedDegrees(to));
        o.put("throws", throwsMade);
        o.put("successes", successes);
        return o;
    }

    /** Radians in degrees to 1e-6 (a bin edge of 11 pi / 4 reads 495, not 494.99999999999994). */
    private static double roundedDegrees(double radians) {
        return Math.round(Math.toDegrees(radians) * 1e6) / 1e6;
    }

    /** Throws per bin of flight rotation (grey) with the successes among them (blue) drawn over them. */
    private void plotByRotation(List<FlipTask.RotationBin> bins, Path png) throws IOException {
        double[] x = new double[bins.size()], made = new double[bins.size()], succeeded = new double[bins.size()];
        for (int i = 0; i < x.length; i++) {
            FlipTask.RotationBin b = bins.get(i);
            x[i] = Math.toDegrees(b.from() + b.to()) / 2;
            made[i] = b.throwsMade();
            succeeded[i] = b.successes();
        }
        new Plot(String.format(Locale.ROOT, "Throws by flight rotation, %s controller, %s", controllerLabel(), object),
                "rotation of the long axis in flight (deg, bin centre)", "throws")
                .add("throws", x, made, Plot.GREY, Plot.Style.BARS)
                .add("flipped and caught lying in the hand", x, succeeded, Plot.BLUE, Plot.Style.BARS)
                .writePng(png);
    }

    /** A second picture next to --plot: NAME-suffix.png. */
    private Path besidePlot(String suffix) {
        return plot.resolveSibling(plot.getFileName().toString().replaceFirst("\\.png$", "") + suffix + ".png");
    }

    /**
     * Throws that came back to the hand by arrival tilt, how each ended drawn as stacked bars
     * (each bar drawn over the taller one before it): caught lying but not flipped (grey),
     * dropped (red), caught standing (orange), flipped and caught lying (blue).
     */
    private void plotByArrival(List<FlipTask.ArrivalBin> bins, Path png) throws IOException {
        int n = bins.size();
        double[] x = new double[n], all = new double[n], notDropped = new double[n], lying = new double[n], ok = new double[n];
        for (int i = 0; i < n; i++) {
            FlipTask.ArrivalBin b = bins.get(i);
            x[i] = Math.toDegrees(b.from() + b.to()) / 2;
            all[i] = b.throwsMade();
            ok[i] = b.successes();
            lying[i] = b.successes() + b.standing();
            notDropped[i] = b.throwsMade() - b.drops();
        }
        new Plot(String.format(Locale.ROOT, "Throws by arrival tilt, %s controller, %s", controllerLabel(), object),
                "long axis out of the horizontal at the first touch of the catch (deg, bin centre)", "throws")
                .add("dropped", x, all, Plot.RED, Plot.Style.BARS)
                .add("caught, not flipped", x, notDropped, Plot.GREY, Plot.Style.BARS)
                .add("caught standing", x, lying, Plot.ORANGE, Plot.Style.BARS)
                .add("flipped and caught lying", x, ok, Plot.BLUE, Plot.Style.BARS)
                .writePng(png);
    }

    // ---- sensitivity ----------------------------------------------------------------------

    /**
     * --copies: every episode run as seeded and with its launch nudged ({@link LaunchSensitivity}),
     * each copy for --loops throws; the spread of each throw's apex and flight rotation across
     * the copies, per episode and averaged.
     */
    private void evaluateSensitivity(Rollouts rollouts, Function<ThrowTask, ThrowPolicy> policies, ObjectNode out) throws IOException {
        ControllerConfig cc = Runtime.controllerConfig();
        ObjectSpec spec = Runtime.object(object);
        Tasks tasks = Runtime.tasks();
        double[] heightList = heightList();
        List<List<Vec3>> nudges = new ArrayList<>();
        for (int e = 0; e < episodes; e++) {
            nudges.add(LaunchSensitivity.nudges(seed + e, copies, nudge));
        }
        // run j is copy j % copies of episode j / copies; an episode is printed once its copies are in
        List<List<LaunchSensitivity.Spread>> perEpisode = new ArrayList<>();
        List<List<LoopRecord>> copiesDone = new ArrayList<>();
        ArrayNode eps = out.putArray("episodes");
        rollouts.run(episodes * copies, resumable(sim -> {
            ThrowTask t = task.equals("height") ? tasks.height(heightGoals(heightList)) : tasks.create(task, object);
            CatchEvaluation evaluation = evaluation(t, policies, cc, spec);
            return j -> evaluation.run(sim, seed + j / copies, nudges.get(j / copies).get(j % copies), loops, null).loops();
        }, ResultJson::loops, ResultJson::loops), (j, loopsOfCopy) -> {
            copiesDone.add(loopsOfCopy);
            if (copiesDone.size() == copies) {
                List<LaunchSensitivity.Spread> spreads = LaunchSensitivity.spreads(copiesDone);
                copiesDone.clear();
                perEpisode.add(spreads);
                ObjectNode o = eps.addObject();
                o.put("seed", seed + j / copies);
                o.set("throws", spreadsJson(spreads));
                System.out.printf(Locale.ROOT, "episode %d: %s%n", seed + j / copies, spreadsLine(spreads));
            }
        });
        List<LaunchSensitivity.Spread> mean = LaunchSensitivity.mean(perEpisode);
        List<LaunchSensitivity.Spread> median = LaunchSensitivity.median(perEpisode);
        out.put("copies", copies);
        out.put("nudge_m_s", nudge);
        out.put("loops", loops);
        out.set("mean_by_throw", spreadsJson(mean));
        out.set("median_by_throw", spreadsJson(median));
        System.out.printf(Locale.ROOT, "%s task, %s controller, %s, %d episodes x %d copies (launch nudged by %.1e m/s), mean spread "
                + "across copies by throw: %s%n", task, controller, object, episodes, copies, nudge, spreadsLine(mean));
        System.out.printf(Locale.ROOT, "median over episodes: %s%n", spreadsLine(median));
        if (plot != null) {
            boolean rotation = spec.longAxis().isPresent();
            // the spreads span many orders of magnitude (1e-7 mm to tens of degrees): log10 scale
            double[] logMean = log10Spreads(mean, rotation), logMedian = log10Spreads(median, rotation);
            java.util.DoubleSummaryStatistics range = java.util.stream.DoubleStream.concat(java.util.Arrays.stream(logMean),
                    java.util.Arrays.stream(logMedian)).filter(Double::isFinite).summaryStatistics();
            Plot chart = new Plot(String.format(Locale.ROOT, "Launch nudged by %.0e m/s: spread across %d copies, %s controller, %s", nudge, copies,
                    controller, object), "throw", rotation ? "log10 of flight rotation sd (deg)" : "log10 of apex sd (mm)")
                    .add("mean over episodes", throwIndices(mean), logMean, Plot.BLUE, Plot.Style.LINE_POINTS)
                    .add("median over episodes", throwIndices(median), logMedian, Plot.ORANGE, Plot.Style.LINE_POINTS);
            if (range.getCount() > 0) {
                chart.yRange(Math.floor(range.getMin()) - 0.5, Math.ceil(range.getMax()) + 1.5); // room for the legend
            }
            chart.writePng(plot);
            System.out.println("wrote " + plot);
        }
    }

    private static double[] throwIndices(List<LaunchSensitivity.Spread> spreads) {
        return spreads.stream().mapToDouble(LaunchSensitivity.Spread::throwIndex).toArray();
    }

    /** log10 of each throw's flight rotation spread in degrees, or of its apex spread in mm. */
    private static double[] log10Spreads(List<LaunchSensitivity.Spread> spreads, boolean rotation) {
        return spreads.stream().mapToDouble(s -> Math.log10(rotation ? Math.toDegrees(s.rotationSd()) : 1000 * s.apexSd()))
                .toArray();
    }

    private static ArrayNode spreadsJson(List<LaunchSensitivity.Spread> spreads) {
        ArrayNode a = JsonNodeFactory.instance.arrayNode();
        for (LaunchSensitivity.Spread s : spreads) {
            ObjectNode o = a.addObject();
            o.put("throw", s.throwIndex());
            o.put("copies", s.copies());
            putFinite(o, "apex_sd_mm", 1000 * s.apexSd());
            putFinite(o, "flight_rotation_sd_deg", Math.toDegrees(s.rotationSd()));
            putFinite(o, "flight_rotation_range_deg", Math.toDegrees(s.rotationRange()));
        }
        return a;
    }

    /** JSON has no NaN: a figure that could not be measured is null. */
    private static void putFinite(ObjectNode o, String key, double v) {
        if (Double.isFinite(v)) {
            o.put(key, v);
        } else {
            o.putNull(key);
        }
    }

    private static String spreadsLine(List<LaunchSensitivity.Spread> spreads) {
        StringBuilder sb = new StringBuilder();
        for (LaunchSensitivity.Spread s : spreads) {
            sb.append(String.format(Locale.ROOT, "%sthrow %d: apex sd %.3g mm", sb.length() == 0 ? "" : "; ", s.throwIndex(), 1000 * s.apexSd()));
            if (Double.isFinite(s.rotationSd())) {
                sb.append(String.format(Locale.ROOT, ", rotation sd %.3g deg", Math.toDegrees(s.rotationSd())));
            }
            sb.append(" (").append(s.copies()).append(')');
        }
        return sb.length() == 0 ? "no throws" : sb.toString();
    }

    /** The goals listed under {@code key} in a goals file, each with {@code size} numbers. */
    static List<double[]> readGoals(Path file, String key, int size) {
        Json j = Json.load(file);
        List<double[]> out = new ArrayList<>();
        for (Json g : j.array(key)) {
            double[] goal = size == 1 ? new double[] {g.asNumber()} : g.asNumbers(size);
            if (key.equals("heights") && !(goal[0] > HeightGoals.LOWEST && goal[0] < HeightGoals.HIGHEST)) {
                throw g.error("a height goal must lie in (" + HeightGoals.LOWEST + ", " + HeightGoals.HIGHEST + ") m, got "
                        + goal[0]);
            }
            out.add(goal);
        }
        if (out.isEmpty()) {
            throw j.fieldError(key, "at least one goal is needed");
        }
        j.requireNoUnknownFields();
        return out;
    }
}
