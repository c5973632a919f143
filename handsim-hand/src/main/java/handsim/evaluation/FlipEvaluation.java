package handsim.evaluation;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.control.CatchStyle;
import handsim.planning.PlannerConfig;
import handsim.planning.ThrowPlanner;
import handsim.report.Plot;
import handsim.rollout.Rollouts;
import handsim.sim.Simulator;
import handsim.task.FlipTask;
import handsim.task.LoopRecord;
import handsim.task.Rest;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.Supplier;
import java.util.stream.Collectors;

/**
 * The flip task's evaluation (paper sec. 4.4): episodes that run until a throw fails to flip or
 * is dropped (at most {@code loops} in a row), with or without a planner; the summary holds the
 * flip-and-catch loops in a row, how the episodes ended, each throw's success and why the failed
 * ones failed ({@code per_throw}), the throws by flight rotation and by arrival tilt, and the
 * planner's work.
 */
public final class FlipEvaluation extends TaskEvaluation {

    /** The loops plot's height as a multiple of the loop cap: room above the highest bars for the legend. */
    private static final double LEGEND_ROOM = 1.15;

    private final Supplier<FlipTask> tasks;

    /** @param tasks a new task for each worker */
    public FlipEvaluation(EvaluationRequest request, EvaluationSetup setup, Supplier<FlipTask> tasks) {
        super(request, setup);
        this.tasks = tasks;
    }

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

    @Override
    public void run(Rollouts<Simulator> rollouts, ObjectNode out) throws IOException {
        String object = request.object();
        long seed = request.seed();
        int loops = request.loops();
        Path plot = request.plot();
        Path csv = request.csv();
        FlipTask flipTask = tasks.get();
        PlannerConfig planning = setup.planning();
        List<Simulator> twins = Collections.synchronizedList(new ArrayList<>());
        List<FlipRun> runs;
        try {
            runs = rollouts.run(request.episodes(), resumable(sim -> {
                FlipTask t = tasks.get();
                CatchEvaluation evaluation = evaluation(t);
                if (planning != null) {
                    Simulator twin = setup.twins().apply(sim);
                    twins.add(twin);
                    evaluation = evaluation.planned(planning, twin);
                }
                CatchEvaluation worker = evaluation;
                return i -> {
                    // planned episodes take minutes each (the club's up to an hour): say how far they are
                    CatchEvaluation.LoopListener progress = planning == null ? longEpisodeProgress() : (episodeSeed, loop) -> {
                        if (loop.index() > 0 && loop.index() % setup.config().plannedProgressEvery() == 0 && t.success(loop)) {
                            console.printf(Locale.ROOT, "episode %d: %d flip-and-catch loops in a row so far%n", episodeSeed, loop.index());
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
                    flipTask, loops)), (i, r) -> console.printf(Locale.ROOT,
                    "episode %d: %d flip-and-catch loops in a row, %d flips in %d throws, %s%n", r.seed(), r.inARow(), r.flips(),
                    r.throwsMade(), r.ending(object)));
        } finally {
            twins.forEach(Simulator::close);
        }
        if (planning != null) {
            putPlannerStats(out, planning, runs.stream().map(FlipRun::planner).reduce(ThrowPlanner.Stats.NONE, ThrowPlanner.Stats::plus));
        }
        if (csv != null) {
            StringBuilder rows = new StringBuilder("seed,loop,caught,catch_tilt_deg,catch_heading_deg,flips,flight_rotation_deg,"
                    + "release_spin_rad_s,arrival_tilt_deg,apex_m,"
                    + "catch_x,catch_y,catch_z,landing_x,landing_y,landing_z,reward,failure\n");
            for (FlipRun r : runs) {
                for (LoopRecord loop : r.loops()) {
                    rows.append(String.format(Locale.ROOT, "%d,%d,%s,%s,%s,%d,%s,%s,%s,%s,%s,%s,%s,%s%n", r.seed(), loop.index(),
                            loop.caught(),
                            csvNumber(Math.toDegrees(loop.catchTilt())), csvNumber(Math.toDegrees(loop.catchHeading())),
                            flipTask.flips(loop), csvNumber(Math.toDegrees(loop.flightRotation())),
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
        MotionQuality motion = MotionQuality.of(runs.stream().flatMap(r -> r.loops().stream()).toList());
        motion.putInto(out);
        ObjectNode endings = out.putObject("endings");
        for (FlipEnd end : FlipEnd.values()) {
            endings.put(end.label(), runs.stream().filter(r -> r.end() == end).count());
        }
        List<List<LoopRecord>> episodeLoops = runs.stream().map(FlipRun::loops).toList();
        List<LoopRecord> allLoops = episodeLoops.stream().flatMap(List::stream).toList();
        FlipReport report = new FlipReport(flipTask, setup.config().flipBins());
        FlipReport.ThrowTally tally = report.tally(allLoops);
        // each episode's first throw, made from the caught throw-in, and those made from the hand's own catches
        FlipReport.ThrowTally first = report.tally(allLoops.stream().filter(l -> l.index() == 1).toList());
        FlipReport.ThrowTally later = report.tally(allLoops.stream().filter(l -> l.index() > 1).toList());
        putPerThrow(out, tally, first, later);
        List<FlipReport.AngleBin> byHeading = report.firstThrowsByRestHeading(episodeLoops);
        ArrayNode firstByHeading = out.putArray("first_throws_by_rest_heading");
        for (FlipReport.AngleBin b : byHeading) {
            putBin(firstByHeading, b.from(), b.to(), b.throwsMade(), b.successes());
        }
        List<FlipReport.RestCount> byRest = report.laterThrowsByRest(episodeLoops);
        ArrayNode laterByRest = out.putArray("later_throws_by_rest");
        for (FlipReport.RestCount c : byRest) {
            putThrowsAfter(laterByRest.addObject().put("rest", c.rest().label()), c.throwsAfter());
        }
        Optional<FlipReport.CatchDistances> byDistance = report.laterThrowsByCatchDistance(episodeLoops);
        ObjectNode laterByDistance = out.putObject("later_throws_by_catch_distance");
        byDistance.ifPresent(d -> {
            laterByDistance.set("median_catch", ResultJson.vec(d.medianCatch()));
            ArrayNode distanceBins = laterByDistance.putArray("bins");
            for (FlipReport.DistanceCount c : d.bins()) {
                ObjectNode o = distanceBins.addObject().put("from_m", c.from());
                if (Double.isFinite(c.to())) {
                    o.put("to_m", c.to());
                }
                putThrowsAfter(o, c.throwsAfter());
            }
        });
        List<FlipReport.AngleBin> bins = report.byFlightRotation(allLoops);
        ArrayNode byRotation = out.putArray("throws_by_flight_rotation");
        for (FlipReport.AngleBin b : bins) {
            putBin(byRotation, b.from(), b.to(), b.throwsMade(), b.successes());
        }
        List<FlipReport.ArrivalBin> arrivals = report.byArrivalTilt(allLoops);
        ArrayNode byArrival = out.putArray("throws_by_arrival_tilt");
        for (FlipReport.ArrivalBin b : arrivals) {
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
        console.printf(Locale.ROOT, "flip task, %s controller, %s, %d episodes: flip-and-catch loops in a row mean %.2f "
                + "(min %d, max %d, at most %d); %d flips by the successful throws, %d throws; ended by %d drops, %d catches not lying in the hand, "
                + "%d throws that did not flip; %s%n", request.controllerLabel(), object, runs.size(), mean, out.get("loops_completed_min").asInt(),
                out.get("loops_completed_max").asInt(), loops, out.get("flips").asInt(), out.get("throws").asInt(),
                endings.get("dropped").asInt(), endings.get("caught_standing").asInt(), endings.get("no_flip").asInt(), motion.line());
        console.printf(Locale.ROOT, "per throw (%s): %d of %d throws succeed (%.1f %%); failed: %d arrived end-first, %d dropped, "
                + "%d caught standing, %d did not flip%n", method(), tally.successes(), tally.throwsMade(), 100 * tally.successRate(),
                tally.failures().get(FlipTask.Failure.ARRIVED_END_FIRST), tally.failures().get(FlipTask.Failure.DROPPED),
                tally.failures().get(FlipTask.Failure.CAUGHT_STANDING), tally.failures().get(FlipTask.Failure.NO_FLIP));
        console.println("first throws, from the caught throw-in: " + successes(first)
                + "; later throws, from the hand's own catches: " + successes(later));
        console.println("first throws by the heading the throw-in came to rest at (0 across the palm, 90 along the fingers): "
                + byHeading.stream().map(b -> String.format(Locale.ROOT, "%.0f-%.0f deg %d of %d", Math.toDegrees(b.from()),
                        Math.toDegrees(b.to()), b.successes(), b.throwsMade())).collect(Collectors.joining("; ")));
        console.println(String.format(Locale.ROOT, "throws after the first by how the catch before them left the %s (flat: under "
                + "%.0f deg out of the palm's plane; askew: %.0f deg or more from across it), throws 2-%d / from the %dth: ", object,
                Math.toDegrees(Rest.FLAT_TILT), Math.toDegrees(Rest.ASKEW_HEADING), setup.config().flipBins().earlyThrows(), setup.config().flipBins().earlyThrows() + 1)
                + byRest.stream().map(c -> c.rest().label().replace('_', ' ') + " " + earlyAndLater(c.throwsAfter()))
                        .collect(Collectors.joining("; ")));
        byDistance.ifPresent(d -> console.println(String.format(Locale.ROOT, "throws after the first by how far (horizontally) the "
                + "catch before them met the %s from the run's median catch (x %.1f, z %.1f cm), throws 2-%d / from the %dth: ", object,
                100 * d.medianCatch().x(), 100 * d.medianCatch().z(), setup.config().flipBins().earlyThrows(), setup.config().flipBins().earlyThrows() + 1)
                + d.bins().stream().map(c -> (Double.isFinite(c.to()) ? String.format(Locale.ROOT, "%.0f-%.0f cm ", 100 * c.from(),
                        100 * c.to()) : String.format(Locale.ROOT, "over %.0f cm ", 100 * c.from())) + earlyAndLater(c.throwsAfter()))
                        .collect(Collectors.joining("; "))));
        console.println("by the long axis's tilt out of the horizontal when the " + object + " came back to the hand: "
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
                    request.controllerLabel(), object, mean), "episode seed", "loops").add("loops in a row", x, y, Plot.BLUE,
                    Plot.Style.BARS).yRange(0, LEGEND_ROOM * Math.max(1, request.loops())).writePng(plot);
            console.println("wrote " + plot);
            Path rotationPlot = besidePlot("-rotation");
            plotByRotation(bins, rotationPlot);
            console.println("wrote " + rotationPlot);
            Path arrivalPlot = besidePlot("-arrival");
            plotByArrival(arrivals, arrivalPlot);
            console.println("wrote " + arrivalPlot);
        }
    }

    /** Who chose the throws: the paper's method (the controller alone) or the planner on top of it. */
    private String method() {
        return request.plan() ? "planner-assisted" : "paper's method";
    }

    /**
     * The throws the episodes made, each counted on its own (the throw-in left out): how many
     * succeeded and why each failed one failed ({@link FlipTask#failure}), in {@code per_throw},
     * labelled with who chose them ({@code method}); the same for the first throw of each
     * episode, made from the caught throw-in ({@code first_throw}), and for the throws made from
     * the hand's own catches ({@code later_throws}).
     */
    private void putPerThrow(ObjectNode out, FlipReport.ThrowTally all, FlipReport.ThrowTally first, FlipReport.ThrowTally later) {
        out.put("method", method());
        ObjectNode perThrow = putTally(out.putObject("per_throw"), all);
        putTally(perThrow.putObject("first_throw"), first);
        putTally(perThrow.putObject("later_throws"), later);
    }

    /** Writes the counts of some throws after catches: early_throws, early_successes, later_throws, later_successes. */
    private static ObjectNode putThrowsAfter(ObjectNode o, FlipReport.ThrowsAfter t) {
        return o.put("early_throws", t.earlyThrows()).put("early_successes", t.earlySuccesses()).put("later_throws", t.laterThrows())
                .put("later_successes", t.laterSuccesses());
    }

    /** "s of n / s of n": the early throws' successes, then the later ones'. */
    private static String earlyAndLater(FlipReport.ThrowsAfter t) {
        return String.format(Locale.ROOT, "%d of %d / %d of %d", t.earlySuccesses(), t.earlyThrows(), t.laterSuccesses(), t.laterThrows());
    }

    /** "s of n succeed (r %)", or "none made". */
    private static String successes(FlipReport.ThrowTally tally) {
        return tally.throwsMade() == 0 ? "none made"
                : String.format(Locale.ROOT, "%d of %d succeed (%.1f %%)", tally.successes(), tally.throwsMade(), 100 * tally.successRate());
    }

    private static ObjectNode putTally(ObjectNode o, FlipReport.ThrowTally tally) {
        o.put("throws", tally.throwsMade());
        o.put("successes", tally.successes());
        putFinite(o, "success_rate", tally.successRate());
        ObjectNode failures = o.putObject("failures");
        for (FlipTask.Failure f : FlipTask.Failure.values()) {
            failures.put(f.label(), tally.failures().get(f));
        }
        return o;
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
    private void plotByRotation(List<FlipReport.AngleBin> bins, Path png) throws IOException {
        double[] x = new double[bins.size()], made = new double[bins.size()], succeeded = new double[bins.size()];
        for (int i = 0; i < x.length; i++) {
            FlipReport.AngleBin b = bins.get(i);
            x[i] = Math.toDegrees(b.from() + b.to()) / 2;
            made[i] = b.throwsMade();
            succeeded[i] = b.successes();
        }
        new Plot(String.format(Locale.ROOT, "Throws by flight rotation, %s controller, %s", request.controllerLabel(), request.object()),
                "rotation of the long axis in flight (deg, bin centre)", "throws")
                .add("throws", x, made, Plot.GREY, Plot.Style.BARS)
                .add("flipped and caught lying in the hand", x, succeeded, Plot.BLUE, Plot.Style.BARS)
                .writePng(png);
    }

    /** A second picture next to --plot: NAME-suffix.png. */
    private Path besidePlot(String suffix) {
        Path plot = request.plot();
        return plot.resolveSibling(plot.getFileName().toString().replaceFirst("\\.png$", "") + suffix + ".png");
    }

    /**
     * Throws that came back to the hand by arrival tilt, how each ended drawn as stacked bars
     * (each bar drawn over the taller one before it): caught lying but not flipped (grey),
     * dropped (red), caught standing (orange), flipped and caught lying (blue).
     */
    private void plotByArrival(List<FlipReport.ArrivalBin> bins, Path png) throws IOException {
        int n = bins.size();
        double[] x = new double[n], all = new double[n], notDropped = new double[n], lying = new double[n], ok = new double[n];
        for (int i = 0; i < n; i++) {
            FlipReport.ArrivalBin b = bins.get(i);
            x[i] = Math.toDegrees(b.from() + b.to()) / 2;
            all[i] = b.throwsMade();
            ok[i] = b.successes();
            lying[i] = b.successes() + b.standing();
            notDropped[i] = b.throwsMade() - b.drops();
        }
        new Plot(String.format(Locale.ROOT, "Throws by arrival tilt, %s controller, %s", request.controllerLabel(), request.object()),
                "long axis out of the horizontal at the first touch of the catch (deg, bin centre)", "throws")
                .add("dropped", x, all, Plot.RED, Plot.Style.BARS)
                .add("caught, not flipped", x, notDropped, Plot.GREY, Plot.Style.BARS)
                .add("caught standing", x, lying, Plot.ORANGE, Plot.Style.BARS)
                .add("flipped and caught lying", x, ok, Plot.BLUE, Plot.Style.BARS)
                .writePng(png);
    }

    /** The planner's settings and its work over all episodes, printed and in the JSON. */
    private void putPlannerStats(ObjectNode out, PlannerConfig planning, ThrowPlanner.Stats s) {
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
        o.setAll(ResultJson.plannerStats(s));
        console.printf(Locale.ROOT, "planner: %d throws chosen from %d tries (%.1f per throw); for %d of them no try succeeded; "
                + "%d began with the throw the lookahead had found; %d live loops differed from their try in the twin; "
                + "%d throws and %d throw-ins caught otherwise than the controller's own way; %d catches played again from a throw's end%n",
                s.decisions(), s.tries(), s.decisions() == 0 ? 0.0 : (double) s.tries() / s.decisions(), s.unsolved(),
                s.promised(), s.mispredicted(), s.restyledCatches(), s.restyledThrowIns(), s.branches());
    }

    private static void putStyles(ArrayNode out, List<CatchStyle> styles) {
        styles.forEach(c -> out.addObject().put("plane_shift", c.planeShift()).put("velocity_fraction", c.velocityFraction()));
    }
}
