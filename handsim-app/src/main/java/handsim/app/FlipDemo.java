package handsim.app;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Home;
import handsim.control.ThrowPolicy;
import handsim.evaluation.CatchEvaluation;
import handsim.evaluation.FlipReport;
import handsim.report.Outputs;
import handsim.report.Plot;
import handsim.report.Stop;
import handsim.sim.ObjectSpec;
import handsim.sim.Simulator;
import handsim.task.CatchThrowEpisode;
import handsim.task.FlipTask;
import handsim.task.LoopRecord;
import handsim.task.StateVector;
import handsim.taskdef.FlipDefinition;
import handsim.train.ThrowPolicyFile;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * {@code demo --object can|club} without a display: the hand flips the object and catches it,
 * over and over, with the shipped flip policy ({@code models/policies/flip-<object>.json}, the
 * learned controller alone) or, when none ships for the object, the nominal flip. Each throw is
 * printed with its turn in flight and how it ended; a throw that fails only breaks the count of
 * loops in a row, a drop starts the next episode (seed + 1). Writes summary.json, loops.csv and a
 * picture of each throw's turn to the run folder; stopped by a signal, it writes the throws made
 * so far, marked interrupted.
 */
final class FlipDemo {

    private final String object;
    private final long seed;
    private final int throwsWanted;

    FlipDemo(String object, long seed, int throwsWanted) {
        this.object = object;
        this.seed = seed;
        this.throwsWanted = throwsWanted;
    }

    /** The objects the demo flips: those the flip task has settings for. */
    static boolean flips(String object) {
        try {
            flipDefinition().newTask(object);
            return true;
        } catch (IllegalArgumentException e) {
            return false;
        }
    }

    /** The shipped flip policy of {@code object}, or null when none ships (the nominal flip then throws). */
    static Path shippedPolicy(String object) {
        Path file = ThrowPolicyFile.shipped(FlipDefinition.NAME, object);
        return Files.isRegularFile(file) ? file : null;
    }

    /** Runs the throws, printing each, and writes the run folder {@code dir}; {@code exported} (or null) watches every tick. */
    void run(Path dir, RunExport exported) throws IOException {
        FlipTask task = flipDefinition().newTask(object);
        ObjectSpec spec = Wiring.object(object);
        Path policy = shippedPolicy(object);
        Path opening = policy == null ? null : ThrowPolicyFile.shippedOpening(FlipDefinition.NAME, object);
        Path rest = policy == null ? null : ThrowPolicyFile.shippedRest(FlipDefinition.NAME, object);
        ThrowPolicy throwing = policy == null ? obs -> task.nominalThrow()
                : ThrowPolicyFile.throwPolicy(policy, opening, rest, task, spec, StateVector.Hand.of(Wiring.model(null)));
        String controller = policy == null ? "nominal" : "learned";
        CatchEvaluation evaluation = new CatchEvaluation(Wiring.controllerConfig(), Wiring.episodeLimits(), Wiring.launches(), spec,
                task, throwing);
        System.out.printf("handsim demo: flip task, %s, the %s controller%s%n", object, controller,
                policy == null ? " (no flip policy ships for a " + object + ")" : " (" + Home.root().relativize(policy)
                        + (opening == null ? "" : ", " + Home.root().relativize(opening) + " for each episode's first throw")
                        + (rest == null ? "" : ", " + Home.root().relativize(rest) + " for the throws from the rest it serves") + ", alone)");
        List<LoopRecord> made = new ArrayList<>();
        List<Long> seeds = new ArrayList<>();
        int episodes = 0, inARow = 0, longest = 0;
        long t0 = System.nanoTime();
        try (Stop.Watch watch = Stop.watch(); Simulator sim = Wiring.simulator(Wiring.model(null), Wiring.simConfig())) {
            for (long s = seed; made.size() < throwsWanted && !Stop.requested(); s++) {
                episodes++;
                CatchThrowEpisode episode = evaluation.start(sim, s);
                while (episode.status() == CatchThrowEpisode.Status.RUNNING && made.size() < throwsWanted && !Stop.requested()) {
                    LoopRecord r = evaluation.tick(episode, s);
                    if (exported != null) {
                        exported.afterTick(sim);
                    }
                    if (r == null) {
                        continue;
                    }
                    if (r.index() == 0) {
                        System.out.printf("episode %d: %s thrown in, %s%n", s, object, r.caught() ? "caught" : "missed");
                        continue;
                    }
                    made.add(r);
                    seeds.add(s);
                    boolean ok = task.success(r);
                    inARow = ok ? inARow + 1 : 0;
                    longest = Math.max(longest, inARow);
                    System.out.printf(Locale.ROOT, "throw %3d/%d: turned %4.0f deg, %s (%d in a row)%n", made.size(), throwsWanted,
                            Math.toDegrees(r.flightRotation()), ok ? "flipped and caught lying in the hand"
                                    : task.failure(r).orElseThrow().label().replace('_', ' '), inARow);
                }
            }
        }
        write(dir, task, controller, policy, made, seeds, episodes, longest, (System.nanoTime() - t0) / 1e9);
        Stop.check("the " + made.size() + " throws made are in " + dir.resolve("summary.json") + ", marked interrupted");
        if (exported != null) {
            exported.write("handsim demo: flip task, " + object + ", " + controller + " controller, seed " + seed);
        }
    }

    private void write(Path dir, FlipTask task, String controller, Path policy, List<LoopRecord> made, List<Long> seeds, int episodes,
            int longest, double wall) throws IOException {
        FlipReport.ThrowTally tally = new FlipReport(task, Wiring.shipped().evaluation().flipBins()).tally(made);
        ObjectNode summary = JsonNodeFactory.instance.objectNode();
        summary.put("command", "demo");
        summary.put("task", FlipDefinition.NAME);
        summary.put("controller", controller);
        summary.put("policy", policy == null ? null : Home.root().relativize(policy).toString());
        summary.put("object", object);
        summary.put("seed", seed);
        summary.put("throws", tally.throwsMade());
        summary.put("successes", tally.successes());
        summary.put("longest_in_a_row", longest);
        ObjectNode failures = summary.putObject("failures");
        for (FlipTask.Failure f : FlipTask.Failure.values()) {
            failures.put(f.label(), tally.failures().get(f));
        }
        summary.put("episodes", episodes);
        summary.put("wall_s", wall);
        if (Stop.requested()) {
            summary.put("interrupted", Stop.signal() + " after " + made.size() + " of " + throwsWanted + " throws");
        }
        StringBuilder csv = new StringBuilder("throw,episode_seed,flight_rotation_deg,release_spin_rad_s,arrival_tilt_deg,catch_tilt_deg,"
                + "catch_heading_deg,success,failure\n");
        int n = made.size();
        double[] index = new double[n], turn = new double[n];
        List<Double> okIndex = new ArrayList<>(), okTurn = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            LoopRecord r = made.get(i);
            index[i] = i + 1;
            turn[i] = Math.toDegrees(r.flightRotation());
            boolean ok = task.success(r);
            if (ok) {
                okIndex.add(index[i]);
                okTurn.add(turn[i]);
            }
            csv.append(String.format(Locale.ROOT, "%d,%d,%.1f,%.2f,%.1f,%.1f,%.1f,%s,%s%n", i + 1, seeds.get(i), turn[i], r.releaseSpin(),
                    Math.toDegrees(r.arrivalTilt()), Math.toDegrees(r.catchTilt()), Math.toDegrees(r.catchHeading()), ok,
                    task.failure(r).map(FlipTask.Failure::label).orElse("")));
        }
        Outputs.writeJson(dir.resolve("summary.json"), summary);
        Outputs.writeString(dir.resolve("loops.csv"), csv.toString());
        new Plot("Turn in flight per throw (" + object + ", " + controller + " controller)", "throw", "end-over-end turn (deg)")
                .add("throw", index, turn, Plot.GREY, Plot.Style.POINTS)
                .add("flipped and caught lying", okIndex.stream().mapToDouble(Double::doubleValue).toArray(),
                        okTurn.stream().mapToDouble(Double::doubleValue).toArray(), Plot.BLUE, Plot.Style.POINTS)
                .writePng(dir.resolve("rotation.png"));
        System.out.printf(Locale.ROOT, "%d throws: %d flipped and caught lying in the hand (%.1f %%), at most %d in a row (%d episodes); "
                + "%.0f s%n", n, tally.successes(), 100 * tally.successRate(), longest, episodes, wall);
        System.out.println("wrote " + dir.resolve("summary.json") + ", loops.csv, rotation.png");
    }

    /** The shipped flip task's definition. */
    private static FlipDefinition flipDefinition() {
        return Wiring.shipped().flip();
    }
}
