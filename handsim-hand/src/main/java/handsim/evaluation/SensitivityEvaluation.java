package handsim.evaluation;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.math.Vec3;
import handsim.report.Plot;
import handsim.rollout.Rollouts;
import handsim.sim.ObjectSpec;
import handsim.sim.Simulator;
import handsim.task.LoopRecord;
import handsim.task.ThrowTask;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.DoubleSummaryStatistics;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;
import java.util.stream.DoubleStream;

/**
 * How far a tiny difference carries through the loops (height or flip task): every episode run
 * as seeded and with its launch velocity nudged in random directions ({@link LaunchSensitivity}),
 * each copy for {@code loops} throws whether they succeed or not; the spread of each throw's apex
 * and flight rotation across the copies, per episode, and its mean and median over episodes.
 */
public final class SensitivityEvaluation extends TaskEvaluation {

    private final Supplier<ThrowTask> tasks;

    /** @param tasks a new task for each worker */
    public SensitivityEvaluation(EvaluationRequest request, EvaluationSetup setup, Supplier<ThrowTask> tasks) {
        super(request, setup);
        this.tasks = tasks;
    }

    @Override
    public void run(Rollouts<Simulator> rollouts, ObjectNode out) throws IOException {
        String task = request.task();
        String object = request.object();
        String controller = request.controller();
        long seed = request.seed();
        int loops = request.loops();
        int episodes = request.episodes();
        int copies = request.copies();
        double nudge = request.nudge();
        Path plot = request.plot();
        ObjectSpec spec = setup.object();
        List<List<Vec3>> nudges = new ArrayList<>();
        for (int e = 0; e < episodes; e++) {
            nudges.add(LaunchSensitivity.nudges(seed + e, copies, nudge));
        }
        // run j is copy j % copies of episode j / copies; an episode is printed once its copies are in
        List<List<LaunchSensitivity.Spread>> perEpisode = new ArrayList<>();
        List<List<LoopRecord>> copiesDone = new ArrayList<>();
        List<LaunchSensitivity.CopyFigures> figures = new ArrayList<>();
        ArrayNode eps = out.putArray("episodes");
        rollouts.run(episodes * copies, resumable(sim -> {
            CatchEvaluation evaluation = evaluation(tasks.get());
            return j -> evaluation.run(sim, seed + j / copies, nudges.get(j / copies).get(j % copies), loops, null).loops();
        }, ResultJson::loops, ResultJson::loops), (j, loopsOfCopy) -> {
            copiesDone.add(loopsOfCopy);
            if (copiesDone.size() == copies) {
                List<LaunchSensitivity.Spread> spreads = LaunchSensitivity.spreads(copiesDone);
                List<LaunchSensitivity.CopyFigures> episodeFigures = new ArrayList<>();
                for (int c = 0; c < copies; c++) {
                    episodeFigures.add(LaunchSensitivity.CopyFigures.of(c, copiesDone.get(c)));
                }
                copiesDone.clear();
                perEpisode.add(spreads);
                figures.addAll(episodeFigures);
                ObjectNode o = eps.addObject();
                o.put("seed", seed + j / copies);
                o.set("throws", spreadsJson(spreads));
                o.set("copies", figuresJson(episodeFigures));
                console.printf(Locale.ROOT, "episode %d: %s%n", seed + j / copies, spreadsLine(spreads));
                console.printf(Locale.ROOT, "episode %d by copy: %s%n", seed + j / copies, figuresLine(episodeFigures));
            }
        });
        List<LaunchSensitivity.Spread> mean = LaunchSensitivity.mean(perEpisode);
        List<LaunchSensitivity.Spread> median = LaunchSensitivity.median(perEpisode);
        out.put("copies", copies);
        out.put("nudge_m_s", nudge);
        out.put("loops", loops);
        out.set("mean_by_throw", spreadsJson(mean));
        out.set("median_by_throw", spreadsJson(median));
        out.put("drops", figures.stream().mapToInt(LaunchSensitivity.CopyFigures::drops).sum());
        List<Double> heightErrors = figures.stream().map(LaunchSensitivity.CopyFigures::heightAbsError).filter(Double::isFinite).toList();
        if (!heightErrors.isEmpty()) {
            // the headline figure of every copy: how far a nudge alone moves a run's mean |error|
            ObjectNode h = out.putObject("height_error_abs_mean_over_copies");
            putFinite(h, "mean", LaunchSensitivity.average(heightErrors));
            putFinite(h, "sd", LaunchSensitivity.sd(heightErrors));
            h.put("min", heightErrors.stream().mapToDouble(Double::doubleValue).min().orElseThrow());
            h.put("max", heightErrors.stream().mapToDouble(Double::doubleValue).max().orElseThrow());
            console.printf(Locale.ROOT, "|height error| mean over %d copies: %.4f m, sd %.4f m, from %.4f to %.4f m; drops %d%n",
                    heightErrors.size(), h.get("mean").asDouble(), h.get("sd").asDouble(), h.get("min").asDouble(),
                    h.get("max").asDouble(), out.get("drops").asInt());
        }
        console.printf(Locale.ROOT, "%s task, %s controller, %s, %d episodes x %d copies (launch nudged by %.1e m/s), mean spread "
                + "across copies by throw: %s%n", task, controller, object, episodes, copies, nudge, spreadsLine(mean));
        console.printf(Locale.ROOT, "median over episodes: %s%n", spreadsLine(median));
        if (plot != null) {
            boolean rotation = spec.longAxis().isPresent();
            // the spreads span many orders of magnitude (1e-7 mm to tens of degrees): log10 scale
            double[] logMean = log10Spreads(mean, rotation), logMedian = log10Spreads(median, rotation);
            DoubleSummaryStatistics range = DoubleStream.concat(Arrays.stream(logMean),
                    Arrays.stream(logMedian)).filter(Double::isFinite).summaryStatistics();
            Plot chart = new Plot(String.format(Locale.ROOT, "Launch nudged by %.0e m/s: spread across %d copies, %s controller, %s", nudge, copies,
                    controller, object), "throw", rotation ? "log10 of flight rotation sd (deg)" : "log10 of apex sd (mm)")
                    .add("mean over episodes", throwIndices(mean), logMean, Plot.BLUE, Plot.Style.LINE_POINTS)
                    .add("median over episodes", throwIndices(median), logMedian, Plot.ORANGE, Plot.Style.LINE_POINTS);
            if (range.getCount() > 0) {
                chart.yRange(Math.floor(range.getMin()) - 0.5, Math.ceil(range.getMax()) + 1.5); // room for the legend
            }
            chart.writePng(plot);
            console.println("wrote " + plot);
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
        return jsonArray(spreads, (s, o) -> {
            o.put("throw", s.throwIndex());
            o.put("copies", s.copies());
            putFinite(o, "apex_sd_mm", 1000 * s.apexSd());
            putFinite(o, "flight_rotation_sd_deg", Math.toDegrees(s.rotationSd()));
            putFinite(o, "flight_rotation_range_deg", Math.toDegrees(s.rotationRange()));
        });
    }

    private static ArrayNode figuresJson(List<LaunchSensitivity.CopyFigures> figures) {
        return jsonArray(figures, (f, o) -> {
            o.put("copy", f.copy());
            o.put("throws", f.throwsMade());
            o.put("drops", f.drops());
            putFinite(o, "height_error_abs_mean", f.heightAbsError());
        });
    }

    /** A JSON array with one object per item, its fields written by {@code fields}. */
    private static <T> ArrayNode jsonArray(List<T> items, java.util.function.BiConsumer<T, ObjectNode> fields) {
        ArrayNode a = JsonNodeFactory.instance.arrayNode();
        items.forEach(item -> fields.accept(item, a.addObject()));
        return a;
    }

    private static String figuresLine(List<LaunchSensitivity.CopyFigures> figures) {
        StringBuilder sb = new StringBuilder();
        for (LaunchSensitivity.CopyFigures f : figures) {
            sb.append(String.format(Locale.ROOT, "%scopy %d: %d throws, %d drops", sb.length() == 0 ? "" : "; ", f.copy(),
                    f.throwsMade(), f.drops()));
            if (Double.isFinite(f.heightAbsError())) {
                sb.append(String.format(Locale.ROOT, ", |error| %.4f m", f.heightAbsError()));
            }
        }
        return sb.toString();
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
}
