package handsim.evaluation;

import handsim.math.Vec3;
import handsim.report.Plot;
import handsim.sim.Simulator;
import handsim.task.BoxTask;
import handsim.task.LoopRecord;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * The box task's evaluation (paper sec. 4.3, Fig. 8): the box is fixed at a position and the
 * hand throws and catches; a trial succeeds after {@code required} consecutive hit-and-catch
 * loops (6 in the paper) and fails at the first loop that misses the box or drops the object.
 * Success is reported against the box's distance from the centre of its region.
 */
public final class BoxTrials {

    /**
     * One trial.
     *
     * @param box the box centre (m, world)
     * @param distance its distance from the region's centre (m)
     * @param inARow hit-and-catch loops in a row before the test ended
     * @param motion the motion figures over the trial's loops
     */
    public record Trial(int index, long seed, Vec3 box, double distance, boolean success, int inARow, MotionQuality motion) {
    }

    private BoxTrials() {
    }

    /** Runs one trial of {@code evaluation} (on the box task {@code task}) with the box at {@code box}. */
    public static Trial run(CatchEvaluation evaluation, BoxTask task, Simulator sim, int index, long seed, Vec3 box,
            int required) {
        task.placeAt(box);
        List<LoopRecord> loops = evaluation.runWhileSuccessful(sim, seed, required);
        int inARow = evaluation.successesInARow(loops);
        return new Trial(index, seed, box, task.distanceFromRegionCenter(box), inARow >= required, inARow, MotionQuality.of(loops));
    }

    /** Share of successful trials (NaN for none). */
    public static double successRate(List<Trial> tests) {
        return tests.isEmpty() ? Double.NaN : tests.stream().filter(Trial::success).count() / (double) tests.size();
    }

    /** Tests whose box lies within [{@code lo}, {@code hi}) of the region's centre. */
    public static List<Trial> band(List<Trial> tests, double lo, double hi) {
        return tests.stream().filter(t -> t.distance() >= lo && t.distance() < hi).toList();
    }

    /**
     * The success map (paper Fig. 8): each test at its box's distance from the region's centre
     * (x) and height above the region's centre (y), successes and failures apart.
     */
    public static void writeMap(Path png, List<Trial> tests, Vec3 regionCenter, String title) throws IOException {
        List<Trial> ok = tests.stream().filter(Trial::success).toList(), failed = tests.stream().filter(t -> !t.success()).toList();
        new Plot(title, "distance of the box from the region's centre (m)", "box height above the region's centre (m)")
                .add(String.format(Locale.ROOT, "success (%d)", ok.size()), distances(ok), heights(ok, regionCenter), Plot.GREEN,
                        Plot.Style.POINTS)
                .add(String.format(Locale.ROOT, "failure (%d)", failed.size()), distances(failed), heights(failed, regionCenter),
                        Plot.RED, Plot.Style.POINTS)
                .writePng(png);
    }

    private static double[] distances(List<Trial> tests) {
        return tests.stream().mapToDouble(Trial::distance).toArray();
    }

    private static double[] heights(List<Trial> tests, Vec3 center) {
        return tests.stream().mapToDouble(t -> t.box().y() - center.y()).toArray();
    }
}
