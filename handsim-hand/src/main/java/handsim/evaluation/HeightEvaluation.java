package handsim.evaluation;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.rollout.Rollouts;
import handsim.sim.Simulator;
import handsim.task.EpisodeResult;
import handsim.task.HeightTask;
import handsim.task.LoopRecord;
import java.io.IOException;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;

/**
 * The height task's evaluation (paper sec. 4.2, Fig. 5): episodes of up to {@code loops} throws,
 * each aiming at its goal apex; the summary holds the catches and drops, the height errors and
 * their histogram, and the natural-motion figures (joint-limit excess, penetration, torque).
 */
public final class HeightEvaluation extends TaskEvaluation {

    private final Supplier<HeightTask> tasks;

    /** @param tasks a new task for each worker, aiming at the request's goals */
    public HeightEvaluation(EvaluationRequest request, EvaluationSetup setup, Supplier<HeightTask> tasks) {
        super(request, setup);
        this.tasks = tasks;
    }

    @Override
    public void run(Rollouts<Simulator> rollouts, ObjectNode out) throws IOException {
        StringBuilder rows = new StringBuilder("episode_seed,loop,caught,apex_m,target_apex_m,landing_x,landing_y,landing_z,"
                + "max_penetration_mm,max_limit_excess_deg,peak_torque_ratio,duration_s\n");
        long seed = request.seed();
        int loops = request.loops();
        // episode i has seed --seed + i on whichever worker runs it; printed in seed order
        List<EpisodeResult> results = rollouts.run(request.episodes(), resumable(sim -> {
            CatchEvaluation evaluation = evaluation(tasks.get());
            return i -> evaluation.run(sim, seed + i, loops, longEpisodeProgress());
        }, ResultJson::episode, ResultJson::episode), (i, r) -> {
            for (LoopRecord loop : r.loops()) {
                console.printf(Locale.ROOT, "episode %d loop %3d: %-7s apex %s%s  penetration %.1f mm  limit excess %.2f deg"
                        + "  torque %.2f%n", r.seed(), loop.index(), loop.caught() ? "caught" : "DROPPED",
                        Double.isNaN(loop.apexHeight()) ? "  -   " : String.format(Locale.ROOT, "%.3f m", loop.apexHeight()),
                        Double.isNaN(loop.targetHeight()) ? "" : String.format(Locale.ROOT, " (goal %.3f, %+.3f)",
                                loop.targetHeight(), loop.apexHeight() - loop.targetHeight()),
                        loop.maxPenetration() * 1e3, Math.toDegrees(loop.maxLimitExcess()), loop.peakTorqueRatio());
                rows.append(csvRow(r.seed(), loop));
            }
            console.printf("episode %d: first catch %s, %d loops completed, %d attempted (%s)%n", r.seed(),
                    r.firstCatch() ? "yes" : "no", r.loopsCompleted(), r.loopsAttempted(), r.status());
        });
        out.put("episodes_requested", request.episodes());
        out.put("loops_per_episode", loops);
        if (request.throwHeight() != null) {
            out.put("throw_height_m", request.throwHeight());
        }
        out.setAll(summarize(results));
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
        // with no throw there is no height error to average (--loops 0): say so rather than print NaN
        String heightErrors = errors.count() == 0 ? "0 throws, no height errors"
                : String.format(Locale.ROOT, "%d throws: height error mean %+.4f m, |error| mean %.4f m, p95 %.4f m, within 0.1 m %.1f %%",
                        errors.count(), errors.mean(), errors.absMean(), errors.absP95(), 100 * errors.within(0.1));
        console.printf(Locale.ROOT, "%s, %s controller, %d episodes: first catch %.0f %%, loops completed %d (mean %.2f), "
                + "drops %d, loops out of time %d; %s; max limit excess %.2f deg, max penetration %.1f mm, peak torque ratio %.2f%n",
                request.object(), request.controller(), request.episodes(), 100 * out.get("first_catch_rate").asDouble(),
                out.get("loops_completed").asInt(), out.get("loops_completed_mean").asDouble(), out.get("drops").asInt(),
                out.get("time_outs").asInt(), heightErrors, out.get("max_limit_excess_deg").asDouble(),
                out.get("max_penetration_mm").asDouble(), out.get("peak_torque_ratio").asDouble());
        writeCsv(rows);
        if (request.plot() != null && errors.count() > 0) {
            errors.writeHistogram(request.plot(), String.format(Locale.ROOT, "Height error, %s controller, %s (%d throws)",
                    request.controller(), request.object(), errors.count()), 0.01);
            console.println("wrote " + request.plot());
        }
    }

    private static String csvRow(long seed, LoopRecord r) {
        return String.format(Locale.ROOT, "%d,%d,%s,%s,%s,%s,%.3f,%.3f,%.3f,%.3f%n", seed, r.index(), r.caught(),
                csvNumber(r.apexHeight()), csvNumber(r.targetHeight()), csvPoint(r.landing()), r.maxPenetration() * 1e3,
                Math.toDegrees(r.maxLimitExcess()), r.peakTorqueRatio(), r.duration());
    }

    /** Aggregate figures: the catches, loops and drops, and the natural-motion figures (limits, penetration, torque). */
    static ObjectNode summarize(List<EpisodeResult> results) {
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
        return s;
    }
}
