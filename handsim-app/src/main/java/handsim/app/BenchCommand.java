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
import handsim.sim.StepAccounting;
import handsim.task.CatchThrowEpisode;
import handsim.task.HeightGoals;
import handsim.task.HeightTask;
import handsim.task.HeldBallScenario;
import handsim.task.ServoLoop;
import handsim.taskdef.HeightDefinition;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
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
import java.util.concurrent.TimeUnit;
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

    /** What one worker measured. */
    private record Run(long steps, double wallS, double cpuS, double stolenS, long bytes, StepAccounting engine, int episodes,
            int loopsCaught, int firstCatches, boolean held, double ballToPalm) {
    }

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
            single = summarize(pass(model, config, thrown, 1, sampler), config);
            sampler.closeWindow();
            print("1 worker", single);
            total = single;
            if (workers > 1) {
                total = summarize(pass(model, config, thrown, workers, null), config);
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
            print(workers + " workers", total);
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
    private List<Run> pass(HandModel model, SimConfig config, ObjectSpec thrown, int n, StackSampler sampler) {
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
    private Run loops(Simulator sim, ObjectSpec thrown, long firstSeed, CyclicBarrier start) {
        Loops loops = new Loops(sim, firstSeed);
        loops.runTo(Math.round(warmup / sim.config().timeStep()));
        await(start);
        Meter meter = new Meter(sim, loops.done);
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
            List<List<Run>> slices = List.of(new ArrayList<>(), new ArrayList<>());
            double[] roundRatios = new double[rounds];
            for (int r = 0; r < rounds; r++) {
                long n = Math.min(sliceSteps, measuredSteps - r * sliceSteps);
                for (int turn = 0; turn < 2; turn++) {
                    int k = (r + turn) % 2;
                    slices.get(k).add(servers[k].slice(n));
                }
                roundRatios[r] = rate(slices.get(0).get(r)) / rate(slices.get(1).get(r));
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
                Run run = sequence(slices.get(k), counts);
                summaries[k] = summarize(List.of(run), config);
                out.set(steppers[k].label(), summaries[k]);
                print(steppers[k].label(), summaries[k]);
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
                    Meter meter = new Meter(sim, loops.done);
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

    /** A {@code --compare} child process, spoken to line by line (see {@link #serveSlices}). */
    private static final class SliceServer implements AutoCloseable {
        static final String READY = "ready", RUN = "run ", SLICE = "slice ", END = "end";
        private final Process process;
        private final BufferedReader from;
        private final PrintStream to;

        SliceServer(List<String> command) throws IOException {
            process = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.INHERIT).start();
            from = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
            to = new PrintStream(process.getOutputStream(), true, StandardCharsets.UTF_8);
        }

        void awaitReady() throws IOException {
            answer(READY);
        }

        Run slice(long steps) throws IOException {
            to.println(RUN + steps);
            String[] f = answer(SLICE).substring(SLICE.length()).split(" ");
            StepAccounting engine = new StepAccounting();
            engine.add(Long.parseLong(f[5]), Long.parseLong(f[6]), Long.parseLong(f[7]), Long.parseLong(f[8]), Long.parseLong(f[9]));
            return new Run(Long.parseLong(f[0]), Double.parseDouble(f[1]), Double.parseDouble(f[2]), Double.parseDouble(f[3]),
                    Long.parseLong(f[4]), engine, 0, 0, 0, false, Double.NaN);
        }

        /** Episodes, catches and first catches since the warm-up. */
        int[] end() throws IOException {
            to.println(END);
            String[] f = answer(END).split(" ");
            return new int[] {Integer.parseInt(f[1]), Integer.parseInt(f[2]), Integer.parseInt(f[3])};
        }

        static String format(Run r) {
            StepAccounting e = r.engine();
            return SLICE + r.steps() + " " + r.wallS() + " " + r.cpuS() + " " + r.stolenS() + " " + r.bytes() + " " + e.stepNanos() + " "
                    + e.collisionNanos() + " " + e.solverNanos() + " " + e.engineBytes() + " " + e.solverBytes();
        }

        /** The child's next line starting with {@code prefix}, other lines skipped. */
        private String answer(String prefix) throws IOException {
            for (String line; (line = from.readLine()) != null; ) {
                if (line.startsWith(prefix)) {
                    return line;
                }
            }
            throw new IllegalStateException("the bench's child process ended without answering (" + prefix.strip() + "): see its output above");
        }

        @Override
        public void close() {
            to.close();
            try {
                if (!process.waitFor(30, TimeUnit.SECONDS)) {
                    process.destroyForcibly();
                }
            } catch (InterruptedException e) {
                process.destroyForcibly();
                Thread.currentThread().interrupt();
            }
        }
    }

    private static double rate(Run r) {
        return r.steps() / r.wallS();
    }

    /** The q-quantile of sorted values, linear between neighbours. */
    private static double quantile(double[] sorted, double q) {
        double x = q * (sorted.length - 1);
        int i = (int) Math.floor(x);
        int j = Math.min(i + 1, sorted.length - 1);
        return sorted[i] + (x - i) * (sorted[j] - sorted[i]);
    }

    /** Slices of one world run one after another, as one run, with its episodes, catches and first catches. */
    private static Run sequence(List<Run> slices, int[] counts) {
        long steps = 0, bytes = 0;
        double wall = 0, cpu = 0, stolen = 0;
        StepAccounting engine = new StepAccounting();
        for (Run r : slices) {
            steps += r.steps();
            wall += r.wallS();
            cpu += r.cpuS();
            stolen += r.stolenS();
            bytes += r.bytes();
            StepAccounting e = r.engine();
            engine.add(e.stepNanos(), e.collisionNanos(), e.solverNanos(), e.engineBytes(), e.solverBytes());
        }
        return new Run(steps, wall, cpu, stolen, bytes, engine, counts[0], counts[1], counts[2], false, Double.NaN);
    }

    /** The arm holds the ball thrown into its palm: the foundation's benchmark. */
    private Run heldBall(Simulator sim, HandModel model, ObjectSpec ball, CyclicBarrier start) {
        HeldBallScenario scenario = new HeldBallScenario(new ServoLoop(sim, Wiring.pd(model)), ball, 0.2, 1);
        long warmSteps = Math.max(Math.round(warmup / sim.config().timeStep()), Math.round(1.0 / sim.config().timeStep()));
        long measuredSteps = Math.round(seconds / sim.config().timeStep());
        for (long i = 0; i < warmSteps; i++) {
            scenario.step();
        }
        await(start);
        Meter meter = new Meter(sim, 0);
        for (long i = 0; i < measuredSteps; i++) {
            scenario.step();
        }
        Site palm = model.site("palm_center");
        Frame palmFrame = sim.bodyFrame(palm.body()).compose(new Frame(palm.position(), palm.orientation()));
        double ballToPalm = palmFrame.origin().distance(sim.objectState().position());
        boolean held = sim.handContacts().any() && ballToPalm < 0.06;
        return meter.finish(measuredSteps, 1, held ? 1 : 0, held ? 1 : 0, held, ballToPalm);
    }

    /** Wall time, this thread's CPU time and allocation from a start. */
    private static final class Meter {
        private static final com.sun.management.ThreadMXBean THREADS =
                (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        final Simulator sim;
        final long steps0;
        final StepAccounting engine0;
        final long t0;
        final long cpu0;
        final long bytes0;
        final double stolen0;

        /** Starts measuring, and counting the engine's own allocation apart. */
        Meter(Simulator sim, long steps0) {
            this.sim = sim;
            this.steps0 = steps0;
            sim.setAccounting(true);
            engine0 = sim.accounting().copy();
            // read before the clocks and the allocation count start: /proc/stat's reading allocates
            stolen0 = HostSteal.seconds();
            t0 = System.nanoTime();
            cpu0 = THREADS.getCurrentThreadCpuTime();
            bytes0 = THREADS.getCurrentThreadAllocatedBytes();
        }

        Run finish(long steps, int episodes, int caught, int firstCatches, boolean held, double ballToPalm) {
            double wallS = (System.nanoTime() - t0) / 1e9;
            double cpuS = (THREADS.getCurrentThreadCpuTime() - cpu0) / 1e9;
            long bytes = THREADS.getCurrentThreadAllocatedBytes() - bytes0;
            Run r = new Run(steps - steps0, wallS, cpuS, HostSteal.seconds() - stolen0, bytes, minus(sim.accounting(), engine0),
                    episodes, caught, firstCatches, held, ballToPalm);
            sim.setAccounting(false);
            return r;
        }
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

    /**
     * Totals of one pass: steps/s is the sum of the workers' steps over the longest worker's
     * wall time (all start together), steps per CPU second is less sensitive to other load.
     */
    private static ObjectNode summarize(List<Run> runs, SimConfig config) {
        long steps = 0, bytes = 0, engineBytes = 0, solverBytes = 0, stepNs = 0, collisionNs = 0, solverNs = 0;
        double wallSum = 0;
        double wall = 0, cpu = 0, stolen = 0;
        int episodes = 0, caught = 0, firstCatches = 0;
        boolean held = true;
        double ballToPalm = 0;
        for (Run r : runs) {
            steps += r.steps();
            bytes += r.bytes();
            engineBytes += r.engine().engineBytes();
            solverBytes += r.engine().solverBytes();
            stepNs += r.engine().stepNanos();
            collisionNs += r.engine().collisionNanos();
            solverNs += r.engine().solverNanos();
            wallSum += r.wallS();
            wall = Math.max(wall, r.wallS());
            // the workers' windows overlap: the longest one's steal is the pass's
            stolen = r.wallS() == wall ? r.stolenS() : stolen;
            cpu += r.cpuS();
            episodes += r.episodes();
            caught += r.loopsCaught();
            firstCatches += r.firstCatches();
            held &= r.held();
            ballToPalm = Math.max(ballToPalm, r.ballToPalm());
        }
        ObjectNode o = JsonNodeFactory.instance.objectNode();
        o.put("workers", runs.size());
        o.put("steps", steps);
        o.put("wall_s", wall);
        o.put("steps_per_s", steps / wall);
        o.put("realtime_factor", steps / wall * config.timeStep());
        o.put("steps_per_cpu_s", steps / cpu);
        if (Double.isFinite(stolen)) {
            o.put("host_steal_share", HostSteal.share(stolen, wall));
        }
        o.put("bytes_per_step", (double) bytes / steps);
        o.put("engine_bytes_per_step", (double) engineBytes / steps);
        o.put("solver_bytes_per_step", (double) solverBytes / steps);
        // where the wall time of the loop goes, timed inside the simulator's step()
        ObjectNode shares = o.putObject("time_shares");
        double wallNs = wallSum * 1e9;
        shares.put("solver", solverNs / wallNs);
        shares.put("collision", collisionNs / wallNs);
        shares.put("engine_glue", (stepNs - solverNs - collisionNs) / wallNs);
        shares.put("controller_pd_episode", Math.max(0, 1 - stepNs / wallNs));
        o.put("handsim_bytes_per_step", (double) (bytes - engineBytes) / steps);
        o.put("allocation_mb_per_s", bytes / wall / 1e6);
        o.put("episodes", episodes);
        o.put("loops_caught", caught);
        o.put("first_catches", firstCatches);
        o.put("ball_held", held);
        if (Double.isFinite(ballToPalm)) {
            o.put("ball_to_palm_m", ballToPalm);
        }
        return o;
    }

    private static void print(String label, ObjectNode o) {
        System.out.printf("  %s: %d steps in %.2f s: %.0f steps/s, %.2fx real time (%.0f steps per CPU second), "
                + "%.0f bytes/step (engine %.0f, of which the constrained step %.0f; controller and loop %.0f); %d episodes, "
                + "%d catches%n", label, o.get("steps").asLong(),
                o.get("wall_s").asDouble(), o.get("steps_per_s").asDouble(), o.get("realtime_factor").asDouble(),
                o.get("steps_per_cpu_s").asDouble(), o.get("bytes_per_step").asDouble(), o.get("engine_bytes_per_step").asDouble(),
                o.get("solver_bytes_per_step").asDouble(), o.get("handsim_bytes_per_step").asDouble(), o.get("episodes").asInt(),
                o.get("loops_caught").asInt());
        if (o.has("host_steal_share")) {
            System.out.printf("    the host took %.1f %% of the CPUs' time (steal)%n", 100 * o.get("host_steal_share").asDouble());
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

    /** The accounting accumulated since {@code from}. */
    private static StepAccounting minus(StepAccounting now, StepAccounting from) {
        StepAccounting d = new StepAccounting();
        d.add(now.stepNanos() - from.stepNanos(), now.collisionNanos() - from.collisionNanos(),
                now.solverNanos() - from.solverNanos(), now.engineBytes() - from.engineBytes(),
                now.solverBytes() - from.solverBytes());
        return d;
    }

    /** The shipped height task's definition. */
    private static HeightDefinition heightDefinition() {
        return Wiring.shipped().height();
    }
}
