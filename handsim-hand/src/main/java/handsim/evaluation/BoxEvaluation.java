package handsim.evaluation;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.math.Vec3;
import handsim.rollout.Rollouts;
import handsim.sim.Simulator;
import handsim.task.BoxTask;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;

/**
 * The box task's evaluation (paper sec. 4.3, Fig. 8): one trial per box position (seeded, or
 * as requested), each a success after the task's loops in a row that hit the box and catch the
 * rebound; the summary holds the success rate by distance from the region's centre and the
 * success map.
 */
public final class BoxEvaluation extends TaskEvaluation {

    private final Supplier<BoxTask> tasks;
    private final List<Vec3> boxes;

    /**
     * @param tasks a new task for each worker
     * @param boxes the box centres to try (m, world), or null for the request's seeded ones
     */
    public BoxEvaluation(EvaluationRequest request, EvaluationSetup setup, Supplier<BoxTask> tasks, List<Vec3> boxes) {
        super(request, setup);
        this.tasks = tasks;
        this.boxes = boxes;
    }

    @Override
    public void run(Rollouts<Simulator> rollouts, ObjectNode out) throws IOException {
        String object = request.object();
        BoxTask reference = tasks.get();
        int required = reference.config().loopsRequired();
        List<Vec3> boxes = new ArrayList<>();
        if (this.boxes != null) {
            boxes.addAll(this.boxes);
        } else {
            for (int i = 0; i < request.tests(); i++) {
                boxes.add(reference.drawCenter(request.seed() + i));
            }
        }
        StringBuilder rows = new StringBuilder("test,seed,box_x,box_y,box_z,distance_m,success,hit_and_catch_in_a_row\n");
        List<BoxTrials.Trial> results = rollouts.run(boxes.size(), resumable(sim -> {
            BoxTask t = tasks.get();
            CatchEvaluation evaluation = evaluation(t);
            return i -> BoxTrials.run(evaluation, t, sim, i, request.seed() + i, boxes.get(i), required);
        }, ResultJson::boxTrial, ResultJson::boxTrial), (i, r) -> {
            console.printf(Locale.ROOT, "test %3d: box (%.3f, %.3f, %.3f), %.3f m from the centre: %s (%d in a row)%n",
                    r.index(), r.box().x(), r.box().y(), r.box().z(), r.distance(), r.success() ? "success" : "failure", r.inARow());
            rows.append(String.format(Locale.ROOT, "%d,%d,%.4f,%.4f,%.4f,%.4f,%s,%d%n", r.index(), r.seed(), r.box().x(),
                    r.box().y(), r.box().z(), r.distance(), r.success(), r.inARow()));
        });
        double radius = reference.regionRadius();
        long successes = results.stream().filter(BoxTrials.Trial::success).count();
        out.put("tests", results.size());
        out.put("successes", successes);
        putRate(out, "success_rate", results);
        out.put("loops_required", required);
        out.put("region_radius_m", radius);
        List<BoxTrials.Trial> inner = BoxTrials.band(results, 0, 0.5 * radius);
        out.put("inner_half_tests", inner.size());
        putRate(out, "inner_half_success_rate", inner);
        ArrayNode bands = out.putArray("by_distance");
        int n = setup.config().boxBands();
        for (int b = 0; b < n; b++) {
            double lo = radius * b / n, hi = b == n - 1 ? Double.POSITIVE_INFINITY : radius * (b + 1) / n;
            List<BoxTrials.Trial> in = BoxTrials.band(results, lo, hi);
            ObjectNode o = bands.addObject();
            o.put("from_m", lo);
            o.put("to_m", Math.min(hi, radius));
            o.put("tests", in.size());
            putRate(o, "success_rate", in);
        }
        MotionQuality motion = results.stream().map(BoxTrials.Trial::motion).reduce(MotionQuality.NONE, MotionQuality::max);
        motion.putInto(out);
        console.printf(Locale.ROOT, "box task, %s controller, %s: %d of %d tests succeeded (%s); inner half of the region "
                + "(within %.3f m of its centre): %s of %d; %s%n", request.controller(), object, successes, results.size(),
                percent(results), 0.5 * radius, percent(inner), inner.size(), motion.line());
        writeCsv(rows);
        if (request.plot() != null) {
            BoxTrials.writeMap(request.plot(), results, reference.regionCenter(), String.format(Locale.ROOT,
                    "Box tests, %s controller (%d of %d succeeded)", request.controller(), successes, results.size()));
            console.println("wrote " + request.plot());
        }
    }

    /** A success rate in the JSON: null for no trials (NaN is not JSON). */
    private static void putRate(ObjectNode node, String field, List<BoxTrials.Trial> trials) {
        putFinite(node, field, trials.isEmpty() ? Double.NaN : BoxTrials.successRate(trials));
    }

    private static String percent(List<BoxTrials.Trial> trials) {
        return trials.isEmpty() ? "no tests" : String.format(Locale.ROOT, "%.1f %%", 100 * BoxTrials.successRate(trials));
    }
}
