package handsim.app;

import handsim.cards.sim.Trajectory;
import handsim.report.Plot;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/**
 * heights.png of a recorded Double Lift trial: how far the top three cards' centroids and the
 * fingertips rose (mm) over the trial, and how much the top card's length between its two short
 * ends shrank under the pinch (mm), from the recorded frames. A lift that grips shows the cards
 * following the fingers; one that does not shows the fingers rising alone.
 */
final class LiftFigure {

    private LiftFigure() {
    }

    static void write(Trajectory t, String title, Path file) throws IOException {
        List<Trajectory.Frame> frames = t.frames();
        double[] time = new double[frames.size()];
        for (int i = 0; i < time.length; i++) {
            time[i] = frames.get(i).time() - frames.get(0).time();
        }
        Plot p = new Plot(title, "time (s)", "mm");
        java.awt.Color[] colours = {Plot.RED, Plot.ORANGE, Plot.BLUE};
        for (int k = 1; k <= 3; k++) {
            p.add("card " + k + " rise", time, rise(t, index(t, "card" + k)), colours[k - 1], Plot.Style.LINE);
        }
        p.add("fingertip rise", time, rise(t, index(t, "finger1")), Plot.GREY, Plot.Style.LINE);
        p.add("card 1 shortened by", time, shortening(t, index(t, "card1")), Plot.GREEN, Plot.Style.LINE);
        p.writePng(file);
    }

    private static int index(Trajectory t, String name) {
        for (int s = 0; s < t.surfaces().size(); s++) {
            if (t.surfaces().get(s).name().equals(name)) {
                return s;
            }
        }
        throw new IllegalArgumentException("the trajectory has no surface " + name);
    }

    /** Rise of a surface's mean z over its first frame (mm). */
    private static double[] rise(Trajectory t, int s) {
        List<Trajectory.Frame> frames = t.frames();
        double[] out = new double[frames.size()];
        double z0 = meanZ(frames.get(0).positions().get(s));
        for (int i = 0; i < out.length; i++) {
            out[i] = 1e3 * (meanZ(frames.get(i).positions().get(s)) - z0);
        }
        return out;
    }

    private static double meanZ(double[] p) {
        double z = 0;
        for (int i = 2; i < p.length; i += 3) {
            z += p[i];
        }
        return z / (p.length / 3);
    }

    /** How much the card's length between the mean x of its two short ends (the first frame's extreme x) shrank (mm). */
    private static double[] shortening(Trajectory t, int s) {
        List<Trajectory.Frame> frames = t.frames();
        double[] first = frames.get(0).positions().get(s);
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < first.length; i += 3) {
            lo = Math.min(lo, first[i]);
            hi = Math.max(hi, first[i]);
        }
        double[] out = new double[frames.size()];
        double l0 = 0;
        for (int f = 0; f < out.length; f++) {
            double[] p = frames.get(f).positions().get(s);
            double a = 0, b = 0;
            int na = 0, nb = 0;
            for (int i = 0; i < p.length; i += 3) {
                if (Math.abs(first[i] - lo) < 1e-6) {
                    a += p[i];
                    na++;
                } else if (Math.abs(first[i] - hi) < 1e-6) {
                    b += p[i];
                    nb++;
                }
            }
            double length = b / nb - a / na;
            l0 = f == 0 ? length : l0;
            out[f] = 1e3 * (l0 - length);
        }
        return out;
    }
}
