package handsim.app;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.model.HandModel;
import handsim.rollout.LocalRollouts;
import handsim.rollout.Rollouts;
import handsim.sim.SimConfig;
import handsim.task.CatchEvaluation;
import handsim.task.EpisodeResult;
import handsim.task.HeightGoals;
import handsim.task.LoopRecord;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code handsim evaluate}: seeded catch-and-throw episodes with the per-loop figures. */
@Command(name = "evaluate", mixinStandardHelpOptions = true,
        description = "Run seeded catch-and-throw episodes: an object is thrown toward the hand (configs/launch.json), "
                + "then the arm catches and throws until a drop or --loops throws. Prints every loop; writes a summary.")
final class EvaluateCommand implements Callable<Integer> {

    @Option(names = "--controller", defaultValue = "nominal", description = "nominal (default)")
    String controller;

    @Option(names = "--object", defaultValue = "sphere", description = "sphere, can, cuboid or club (configs/objects)")
    String object;

    @Option(names = "--loops", defaultValue = "10", description = "throws to attempt per episode after the first catch")
    int loops;

    @Option(names = "--episodes", defaultValue = "1", description = "episodes, seeded --seed, --seed+1, ...")
    int episodes;

    @Option(names = "--seed", defaultValue = "1", description = "seed of the first episode")
    long seed;

    @Option(names = "--throw-height", paramLabel = "H", defaultValue = "1.2",
            description = "desired apex height of every throw (m, world)")
    double throwHeight;

    @Option(names = "--workers", paramLabel = "N",
            description = "episodes run in parallel, each worker with its own engine (default: all local cores); "
                    + "results do not depend on it")
    Integer workers;

    @Option(names = "--json", paramLabel = "FILE", description = "write the summary as JSON")
    Path json;

    @Option(names = "--csv", paramLabel = "FILE", description = "write one row per loop as CSV")
    Path csv;

    @Override
    public Integer call() throws Exception {
        if (!controller.equals("nominal")) {
            throw new IllegalArgumentException("--controller must be nominal (learned controllers come with training), got " + controller);
        }
        if (loops < 0 || loops > 100000) {
            throw new IllegalArgumentException("--loops must be in [0, 100000], got " + loops);
        }
        if (episodes < 1 || episodes > 100000) {
            throw new IllegalArgumentException("--episodes must be in [1, 100000], got " + episodes);
        }
        if (!(throwHeight > 0.7 && throwHeight < 3)) {
            throw new IllegalArgumentException("--throw-height must be in (0.7, 3) m, got " + throwHeight);
        }
        if (workers == null) {
            workers = LocalRollouts.localCores();
        }
        if (workers < 1 || workers > 256) {
            throw new IllegalArgumentException("--workers must be in [1, 256], got " + workers);
        }
        HandModel model = Runtime.model(null);
        SimConfig simConfig = Runtime.simConfig();
        List<EpisodeResult> results;
        StringBuilder rows = new StringBuilder("episode_seed,loop,caught,apex_m,target_apex_m,landing_x,landing_y,landing_z,"
                + "max_penetration_mm,max_limit_excess_deg,peak_torque_ratio,duration_s\n");
        long t0 = System.nanoTime();
        try (Rollouts rollouts = Runtime.rollouts(model, simConfig, workers)) {
            // episode i has seed --seed + i on whichever worker runs it; printed in seed order
            results = rollouts.run(episodes, sim -> {
                CatchEvaluation evaluation = Runtime.nominalEvaluation(object, Runtime.heightTask(HeightGoals.fixed(throwHeight)));
                return i -> evaluation.run(sim, seed + i, loops, null);
            }, (i, r) -> {
                for (LoopRecord loop : r.loops()) {
                    System.out.printf("episode %d loop %3d: %-7s apex %s  penetration %.1f mm  limit excess %.2f deg  torque %.2f%n",
                            r.seed(), loop.index(), loop.caught() ? "caught" : "DROPPED",
                            Double.isNaN(loop.apexHeight()) ? "  -   " : String.format("%.3f m", loop.apexHeight()),
                            loop.maxPenetration() * 1e3, Math.toDegrees(loop.maxLimitExcess()), loop.peakTorqueRatio());
                    rows.append(csvRow(r.seed(), loop));
                }
                System.out.printf("episode %d: first catch %s, %d loops completed, %d attempted (%s)%n", r.seed(),
                        r.firstCatch() ? "yes" : "no", r.loopsCompleted(), r.loopsAttempted(), r.status());
            });
        }
        double wall = (System.nanoTime() - t0) / 1e9;
        ObjectNode summary = summarize(results, wall);
        System.out.printf("%s, %d episodes: first catch %.0f %%, loops completed mean %.2f (min %d, max %d); "
                + "max limit excess %.2f deg, max penetration %.1f mm, peak torque ratio %.2f; %.0f s%n",
                object, episodes, 100 * summary.get("first_catch_rate").asDouble(), summary.get("loops_completed_mean").asDouble(),
                summary.get("loops_completed_min").asInt(), summary.get("loops_completed_max").asInt(),
                summary.get("max_limit_excess_deg").asDouble(), summary.get("max_penetration_mm").asDouble(),
                summary.get("peak_torque_ratio").asDouble(), wall);
        if (json != null) {
            ObjectNode out = JsonNodeFactory.instance.objectNode();
            out.put("controller", controller);
            out.put("object", object);
            out.put("seed", seed);
            out.put("episodes_requested", episodes);
            out.put("loops_per_episode", loops);
            out.put("throw_height_m", throwHeight);
            out.put("workers", workers);
            out.setAll(summary);
            ArrayNode eps = out.putArray("episodes");
            for (EpisodeResult r : results) {
                ObjectNode o = eps.addObject();
                o.put("seed", r.seed());
                o.put("first_catch", r.firstCatch());
                o.put("loops_attempted", r.loopsAttempted());
                o.put("loops_completed", r.loopsCompleted());
                o.put("drops", r.drops());
                o.put("end", r.status().name().toLowerCase());
                o.put("max_limit_excess_deg", Math.toDegrees(r.maxLimitExcess()));
                o.put("max_penetration_mm", r.maxPenetration() * 1e3);
                o.put("peak_torque_ratio", r.peakTorqueRatio());
            }
            Outputs.writeJson(json, out);
            System.out.println("wrote " + json);
        }
        if (csv != null) {
            Outputs.writeString(csv, rows.toString());
            System.out.println("wrote " + csv);
        }
        return 0;
    }

    private static String csvRow(long seed, LoopRecord r) {
        return String.format("%d,%d,%s,%s,%s,%s,%s,%s,%.3f,%.3f,%.3f,%.3f%n", seed, r.index(), r.caught(),
                Double.isNaN(r.apexHeight()) ? "" : String.format("%.4f", r.apexHeight()), Double.isNaN(r.targetHeight()) ? "" : r.targetHeight(),
                r.landing() == null ? "" : String.format("%.4f", r.landing().x()),
                r.landing() == null ? "" : String.format("%.4f", r.landing().y()),
                r.landing() == null ? "" : String.format("%.4f", r.landing().z()),
                r.maxPenetration() * 1e3, Math.toDegrees(r.maxLimitExcess()), r.peakTorqueRatio(), r.duration());
    }

    /** Aggregate figures: the fields plus natural-motion figures (limits, penetration, torque). */
    static ObjectNode summarize(List<EpisodeResult> results, double wallSeconds) {
        ObjectNode s = JsonNodeFactory.instance.objectNode();
        int n = results.size();
        s.put("episodes_run", n);
        s.put("loops_attempted", results.stream().mapToInt(EpisodeResult::loopsAttempted).sum());
        s.put("loops_completed", results.stream().mapToInt(EpisodeResult::loopsCompleted).sum());
        s.put("drops", results.stream().mapToInt(EpisodeResult::drops).sum());
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
}
