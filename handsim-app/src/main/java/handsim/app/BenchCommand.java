package handsim.app;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.evaluation.CatchEvaluation;
import handsim.kin.Frame;
import handsim.model.HandModel;
import handsim.model.Site;
import handsim.report.Outputs;
import handsim.rollout.Rollouts;
import handsim.sim.ObjectSpec;
import handsim.sim.SimConfig;
import handsim.sim.Simulator;
import handsim.task.CatchThrowEpisode;
import handsim.task.HeightGoals;
import handsim.task.HeightTask;
import handsim.task.HeldBallScenario;
import handsim.task.ServoLoop;
import handsim.taskdef.HeightDefinition;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BrokenBarrierException;
import java.util.concurrent.Callable;
import java.util.concurrent.CyclicBarrier;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code handsim bench}: headless throughput of the real workload, catch-and-throw loops of the
 * nominal controller (contacts, IK, PD, FSM), or of the arm holding a ball ({@link
 * HeldBallScenario}). Every worker runs its own world for the same simulated time after a
 * warm-up; with {@code --workers N > 1} a one-worker pass runs first and the speed-up is the
 * ratio of the two totals.
 */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = "Measure physics steps per second, real-time factor, where the time goes (collision, solver, "
                + "controller, IK) and bytes allocated per step, on full catch-throw loops of the nominal controller "
                + "(default) or on the arm holding a ball; --workers N runs N loops in parallel and reports the speed-up.")
final class BenchCommand implements Callable<Integer> {

    @Mixin
    EpisodeOptions episodeOptions;

    @Option(names = "--scenario", defaultValue = "loop",
            description = "loop (catch-throw loops of the nominal controller) or held-ball (default: ${DEFAULT-VALUE})")
    String scenario;

    @Option(names = "--seconds", paramLabel = "S", defaultValue = "10",
            description = "simulated seconds measured per worker, after the warm-up (default: ${DEFAULT-VALUE})")
    double seconds;

    @Option(names = "--warmup", paramLabel = "S", defaultValue = "3",
            description = "simulated seconds of warm-up per worker, not measured (default: ${DEFAULT-VALUE})")
    double warmup;

    @Option(names = "--workers", paramLabel = "N", defaultValue = "1",
            description = "independent loops run in parallel (default: ${DEFAULT-VALUE})")
    int workers;

    @Option(names = "--iterations", paramLabel = "N",
            description = "SOR iterations per step (default: configs/sim.json)")
    Integer iterations;

    @Option(names = "--stepper", paramLabel = "S",
            description = "the constrained step: handsim (handsim's own) or ode4j (ode4j's quickStep) (default: configs/sim.json)")
    String stepper;

    @Option(names = "--compare",
            description = "run handsim's step and ode4j's quickStep side by side, each in a JVM of its own on the same seeds, "
                    + "taking turns of --slice simulated seconds, and report each and the ratio of their steps/s "
                    + "(a slow spell of the machine then falls on both alike); loop scenario, one worker")
    boolean compare;

    /** A {@code --compare} child: runs one world's slices as its parent asks on stdin (see {@link #serveSlices}). */
    @Option(names = "--serve-slices", hidden = true)
    boolean serveSlices;

    @Option(names = "--slice", paramLabel = "S", defaultValue = "0.5",
            description = "with --compare: simulated seconds of one stepper before the other takes over (default: ${DEFAULT-VALUE})")
    double slice;

    @Option(names = "--throw-height", paramLabel = "H", defaultValue = "1.2",
            description = "desired apex height of every throw of the loop scenario (m, world; default: ${DEFAULT-VALUE})")
    double throwHeight;

    @Option(names = "--json", paramLabel = "FILE", description = "write the figures as JSON")
    Path json;

    /** Period of the execution samples for the time shares, ms. */
    private static final long SAMPLE_PERIOD_MS = 10;
    /** Seeds of worker w start at seed + w * WORKER_SEED_STRIDE. */
    private static final long WORKER_SEED_STRIDE = 100_000;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        if (!scenario.equals("loop") && !scenario.equals("held-ball")) {
            throw new IllegalArgumentException("--scenario must be loop or held-ball, got " + scenario);
        }
        if (!(seconds > 0 && seconds <= 3600)) {
            throw new IllegalArgumentException("--seconds must be in (0, 3600], got " + seconds);
        }
        if (!(warmup >= 0 && warmup <= 600)) {
            throw new IllegalArgumentException("--warmup must be in [0, 600], got " + warmup);
        }
        if (workers < 1 || workers > 256) {
            throw new IllegalArgumentException("--workers must be in [1, 256], got " + workers);
        }
        HeightTask.Config height = heightDefinition().config();
        if (!height.allowsGoal(throwHeight)) {
            throw new IllegalArgumentException("--throw-height must be in " + height.goalLimits() + ", got " + throwHeight);
        }
        if (iterations != null && (iterations < 1 || iterations > 1000)) {
            throw new IllegalArgumentException("--iterations must be in [1, 1000], got " + iterations);
        }
        SimConfig.Stepper chosen = stepper != null ? SimConfig.Stepper.named("--stepper", stepper) : null;
        if (compare && (stepper != null || workers != 1 || !scenario.equals("loop"))) {
            throw new IllegalArgumentException("--compare runs both steppers in the loop scenario on one worker: "
                    + "drop --stepper, --workers and --scenario");
        }
        if (compare && !(slice > 0 && slice <= seconds)) {
            throw new IllegalArgumentException("--slice must be in (0, --seconds], got " + slice);
        }
        new OutputPaths().file("--json", json).check();
        String commit = Provenance.gitCommit(); // the code the figures are of
        HandModel model = Wiring.model(null);
        SimConfig base = Wiring.simConfig();
        SimConfig iterated = iterations != null ? base.withSolverIterations(iterations) : base;
        SimConfig config = chosen != null ? iterated.withStepper(chosen) : iterated;
        ObjectSpec thrown = Wiring.object(scenario.equals("held-ball") ? "sphere" : episodeOptions.object);
        if (serveSlices) {
            return serveSlices(model, config);
        }
        if (compare) {
            return compare(config, thrown, commit);
        }

        System.out.printf("bench %s: %d worker%s, %.0f s warm-up + %.0f s measured per worker, h = %.1f ms, "
                + "%s step, %d iterations%n", scenario, workers, workers > 1 ? "s" : "", warmup, seconds,
                config.timeStep() * 1e3, config.stepper().label(), config.solverIterations());
        ObjectNode out = JsonNodeFactory.instance.objectNode();
        out.put("scenario", scenario);
        out.put("object", thrown.name());
        out.put("time_step_s", config.timeStep());
        out.put("stepper", config.stepper().label());
        out.put("solver_iterations", config.solverIterations());
        out.put("seconds_per_worker", seconds);
        out.put("workers", workers);

        ObjectNode single;
        ObjectNode total;
        Map<String, Double> shares;
        int samples;
        // the sampler runs through both passes, so that its small cost is the same in each; it
        // counts the one-worker pass only
        try (StackSampler sampler = new StackSampler(SAMPLE_PERIOD_MS)) {
            single = BenchRun.summarize(pass(model, config, thrown, 1, sampler), config);
            sampler.closeWindow();
            BenchRun.print("1 worker", single);
            total = single;
            if (workers > 1) {
                total = BenchRun.summarize(pass(model, config, thrown, workers, null), config);
            }
            sampler.stop();
            shares = sampler.shares();
            samples = sampler.samples();
        }
        System.out.printf("  time shares (timed in step()): %s%n", formatShares(single.get("time_shares")));
        // JFR's execution samples skip threads in native code (StrictMath), so only the IK's
        // share, pure Java inside the controller, is read from them
        System.out.printf("  of which DLS IK: %.1f %% (%d JFR execution samples)%n", 100 * shares.get("ik"), samples);
        if (workers > 1) {
            BenchRun.print(workers + " workers", total);
        }
        double speedup = total.get("steps_per_s").asDouble() / single.get("steps_per_s").asDouble();
        if (workers > 1) {
            System.out.printf("  speed-up over 1 worker: %.2fx%n", speedup);
        }
        out.put("steps_per_s", total.get("steps_per_s").asDouble());
        out.put("realtime_factor", total.get("realtime_factor").asDouble());
        out.put("bytes_per_step", total.get("bytes_per_step").asDouble());
        out.put("speedup", speedup);
        out.set("single_worker", single);
        ObjectNode shareNode = single.putObject("sampled_shares");
        shares.forEach(shareNode::put);
        single.put("sampled_share_samples", samples);
        if (workers > 1) {
            out.set("parallel", total);
        }
        out.set("provenance", Provenance.of(spec.commandLine().getParseResult().originalArgs(), commit));
        if (json != null) {
            Outputs.writeJson(json, out);
            System.out.println("wrote " + json);
        }
        boolean ok = scenario.equals("held-ball") ? single.get("ball_held").asBoolean() : single.get("loops_caught").asInt() > 0;
        return ok ? 0 : 1;
    }

    /** Runs {@code n} workers at once, each on its own engine, measuring after a common start. */
    private List<BenchRun> pass(HandModel model, SimConfig config, ObjectSpec thrown, int n, StackSampler sampler) {
        CyclicBarrier measuredStart = new CyclicBarrier(n, () -> {
            if (sampler != null) {
                sampler.start();
            }
        });
        try (Rollouts<Simulator> rollouts = Wiring.rollouts(model, config, n)) {
            return rollouts.run(n, sim -> worker -> {
                if (sampler != null) {
                    sampler.register();
                }
                return scenario.equals("held-ball") ? heldBall(sim, model, thrown, measuredStart)
                        : loops(sim, thrown, episodeOptions.seed + worker * WORKER_SEED_STRIDE, measuredStart);
            });
        }
    }

    /** Catch-throw episodes one after another (a drop starts the next seed) for warm-up + measured time. */
    private BenchRun loops(Simulator sim, ObjectSpec thrown, long firstSeed, CyclicBarrier start) {
        Loops loops = new Loops(sim, firstSeed);
        loops.runTo(Math.round(warmup / sim.config().timeStep()));
        await(start);
        BenchMeter meter = new BenchMeter(sim, loops.done);
        loops.resetCounts();
        loops.runTo(meter.steps0 + Math.round(seconds / sim.config().timeStep()));
        return meter.finish(loops.done, loops.episodes, loops.caught, loops.firstCatches, false, Double.NaN);
    }

    /** Catch-throw episodes of one world one after another, a drop starting the next seed, run in stretches. */
    private final class Loops {
        final Simulator sim;
        final CatchEvaluation evaluation;
        long seed;
        CatchThrowEpisode episode;
        /** Steps run so far. */
        long done;
        int episodes = 1, caught, firstCatches;

        Loops(Simulator sim, long firstSeed) {
            this.sim = sim;
            HeightTask task = heightDefinition().newTask(HeightGoals.fixed(throwHeight));
            evaluation = CatchEvaluation.nominal(Wiring.controllerConfig(), Wiring.episodeLimits(), Wiring.launches(),
                    Wiring.object(episodeOptions.object), task);
            seed = firstSeed;
            episode = evaluation.start(sim, seed);
        }

        /** Runs control ticks until {@code steps} steps are done in all. */
        void runTo(long steps) {
            while (done < steps) {
                long before = sim.stepCount();
                var loop = evaluation.tick(episode, seed);
                done += sim.stepCount() - before;
                if (loop != null && loop.caught()) {
                    caught++;
                    firstCatches += loop.index() == 0 ? 1 : 0;
                }
                if (episode.status() != CatchThrowEpisode.Status.RUNNING) {
                    episode = evaluation.start(sim, ++seed);
                    episodes++;
                }
            }
        }

        /** Counts episodes and catches from here on, the running episode the first. */
        void resetCounts() {
            episodes = 1;
            caught = 0;
            firstCatches = 0;
        }
    }

    /**
     * {@code --compare}: one JVM per stepper (this command again, with {@code --serve-slices}),
     * each running one world on the same seeds; both warm up, then they take turns of {@code
     * --slice} simulated seconds, which goes first alternating, until each has run {@code
     * --seconds}. Only one runs at a time, the other waits on its input. A round is one slice of
     * each; its ratio of steps/s is measured within a second or so, so a slow spell of the machine
     * falls on both, and neither world's code shares its JVM, or the JIT's view of it, with the other's.
     */
    private Integer compare(SimConfig config, ObjectSpec thrown, String commit) throws Exception {
        SimConfig.Stepper[] steppers = {SimConfig.Stepper.HANDSIM, SimConfig.Stepper.ODE4J};
        double h = config.timeStep();
        long sliceSteps = Math.round(slice / h);
        long measuredSteps = Math.round(seconds / h);
        int rounds = (int) ((measuredSteps + sliceSteps - 1) / sliceSteps);
        System.out.printf("bench loop, compared: handsim's step and ode4j's quickStep, a JVM each, %.0f s warm-up, then "
                + "%d rounds of %.2f s each, h = %.1f ms, %d iterations%n", warmup, rounds, slice, h * 1e3, config.solverIterations());
        SliceServer[] servers = new SliceServer[2];
        try {
            for (int k = 0; k < 2; k++) {
                servers[k] = new SliceServer(childCommand(steppers[k]));
            }
            for (SliceServer server : servers) {
                server.awaitReady();
            }
            List<List<BenchRun>> slices = List.of(new ArrayList<>(), new ArrayList<>());
            double[] roundRatios = new double[rounds];
            for (int r = 0; r < rounds; r++) {
                long n = Math.min(sliceSteps, measuredSteps - r * sliceSteps);
                for (int turn = 0; turn < 2; turn++) {
                    int k = (r + turn) % 2;
                    slices.get(k).add(servers[k].slice(n));
                }
                roundRatios[r] = slices.get(0).get(r).stepsPerSecond() / slices.get(1).get(r).stepsPerSecond();
            }
            ObjectNode out = JsonNodeFactory.instance.objectNode();
            out.put("scenario", "loop");
            out.put("object", thrown.name());
            out.put("time_step_s", h);
            out.put("solver_iterations", config.solverIterations());
            out.put("seconds_per_stepper", seconds);
            out.put("slice_s", slice);
            out.put("rounds", rounds);
            ObjectNode[] summaries = new ObjectNode[2];
            for (int k = 0; k < 2; k++) {
                int[] counts = servers[k].end();
                BenchRun run = BenchRun.sequence(slices.get(k), counts);
                summaries[k] = BenchRun.summarize(List.of(run), config);
                out.set(steppers[k].label(), summaries[k]);
                BenchRun.print(steppers[k].label(), summaries[k]);
            }
            double ratio = summaries[0].get("steps_per_s").asDouble() / summaries[1].get("steps_per_s").asDouble();
            double cpuRatio = summaries[0].get("steps_per_cpu_s").asDouble() / summaries[1].get("steps_per_cpu_s").asDouble();
            Arrays.sort(roundRatios);
            double q1 = quantile(roundRatios, 0.25), median = quantile(roundRatios, 0.5), q3 = quantile(roundRatios, 0.75);
            out.put("ratio_steps_per_s", ratio);
            out.put("ratio_steps_per_cpu_s", cpuRatio);
            ObjectNode rr = out.putObject("round_ratios");
            rr.put("median", median);
            rr.put("q1", q1);
            rr.put("q3", q3);
            rr.put("min", roundRatios[0]);
            rr.put("max", roundRatios[rounds - 1]);
            System.out.printf("  handsim's step / ode4j's quickStep: %.2fx the steps/s (%.2fx per CPU second); "
                    + "the %d rounds' ratios: median %.2f, middle half %.2f-%.2f, all %.2f-%.2f%n", ratio, cpuRatio, rounds, median, q1,
                    q3, roundRatios[0], roundRatios[rounds - 1]);
            out.set("provenance", Provenance.of(spec.commandLine().getParseResult().originalArgs(), commit));
            if (json != null) {
                Outputs.writeJson(json, out);
                System.out.println("wrote " + json);
            }
            return summaries[0].get("loops_caught").asInt() > 0 && summaries[1].get("loops_caught").asInt() > 0 ? 0 : 1;
        } finally {
            for (SliceServer server : servers) {
                if (server != null) {
                    server.close();
                }
            }
        }
    }

    /** This JVM's command line for a {@code --compare} child stepping with {@code stepper}. */
    private List<String> childCommand(SimConfig.Stepper stepper) {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        for (String arg : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            // the JVM's settings (heap, collector, handsim.home), not a recording or a debugger of this one
            if (!arg.startsWith("-XX:StartFlightRecording") && !arg.startsWith("-agentlib") && !arg.startsWith("-javaagent")) {
                command.add(arg);
            }
        }
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), Main.class.getName(), "bench", "--serve-slices",
                "--stepper", stepper.label(), "--warmup", Double.toString(warmup), "--seed", Long.toString(episodeOptions.seed),
                "--object", episodeOptions.object, "--throw-height", Double.toString(throwHeight)));
        if (iterations != null) {
            command.addAll(List.of("--iterations", Integer.toString(iterations)));
        }
        return command;
    }

    /**
     * The child's side of {@code --compare}: one world warms up and says {@code ready}; then each
     * line {@code run N} runs N more steps and answers with their measurement, and {@code end}
     * answers with the episodes and catches since the warm-up. Nothing else goes to stdout.
     */
    private Integer serveSlices(HandModel model, SimConfig config) throws Exception {
        try (Simulator sim = Wiring.isolatedSimulator(model, config)) {
            Loops loops = new Loops(sim, episodeOptions.seed);
            loops.runTo(Math.round(warmup / config.timeStep()));
            loops.resetCounts();
            long target = loops.done;
            BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
            System.out.println(SliceServer.READY);
            for (String line; (line = in.readLine()) != null; ) {
                if (line.startsWith(SliceServer.RUN)) {
                    target += Long.parseLong(line.substring(SliceServer.RUN.length()));
                    BenchMeter meter = new BenchMeter(sim, loops.done);
                    loops.runTo(target);
                    System.out.println(SliceServer.format(meter.finish(loops.done, 0, 0, 0, false, Double.NaN)));
                } else if (line.equals(SliceServer.END)) {
                    System.out.println(SliceServer.END + " " + loops.episodes + " " + loops.caught + " " + loops.firstCatches);
                    return 0;
                }
            }
            return 1; // the parent went away
        }
    }

    /** The q-quantile of sorted values, linear between neighbours. */
    private static double quantile(double[] sorted, double q) {
        double x = q * (sorted.length - 1);
        int i = (int) Math.floor(x);
        int j = Math.min(i + 1, sorted.length - 1);
        return sorted[i] + (x - i) * (sorted[j] - sorted[i]);
    }

    /** The arm holds the ball thrown into its palm: the foundation's benchmark. */
    private BenchRun heldBall(Simulator sim, HandModel model, ObjectSpec ball, CyclicBarrier start) {
        HeldBallScenario scenario = new HeldBallScenario(new ServoLoop(sim, Wiring.pd(model)), ball, 0.2, 1);
        long warmSteps = Math.max(Math.round(warmup / sim.config().timeStep()), Math.round(1.0 / sim.config().timeStep()));
        long measuredSteps = Math.round(seconds / sim.config().timeStep());
        for (long i = 0; i < warmSteps; i++) {
            scenario.step();
        }
        await(start);
        BenchMeter meter = new BenchMeter(sim, 0);
        for (long i = 0; i < measuredSteps; i++) {
            scenario.step();
        }
        Site palm = model.site("palm_center");
        Frame palmFrame = sim.bodyFrame(palm.body()).compose(new Frame(palm.position(), palm.orientation()));
        double ballToPalm = palmFrame.origin().distance(sim.objectState().position());
        boolean held = sim.handContacts().any() && ballToPalm < 0.06;
        return meter.finish(measuredSteps, 1, held ? 1 : 0, held ? 1 : 0, held, ballToPalm);
    }

    private static void await(CyclicBarrier barrier) {
        try {
            barrier.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        } catch (BrokenBarrierException e) {
            throw new IllegalStateException("another worker failed", e);
        }
    }

    private static String formatShares(Map<String, Double> shares) {
        StringBuilder b = new StringBuilder();
        shares.forEach((k, v) -> b.append(b.length() > 0 ? ", " : "").append(String.format("%s %.1f %%", k, 100 * v)));
        return b.toString();
    }

    private static String formatShares(com.fasterxml.jackson.databind.JsonNode shares) {
        Map<String, Double> m = new java.util.LinkedHashMap<>();
        shares.fields().forEachRemaining(e -> m.put(e.getKey(), e.getValue().asDouble()));
        return formatShares(m);
    }

    /** The shipped height task's definition. */
    private static HeightDefinition heightDefinition() {
        return Wiring.shipped().height();
    }
}
