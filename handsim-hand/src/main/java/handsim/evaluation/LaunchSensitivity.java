package handsim.evaluation;

import handsim.task.LoopRecord;

import handsim.math.Vec3;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

/**
 * How far one episode's outcomes drift apart when its launch is nudged. Copy 0 is the episode
 * as seeded; every other copy adds a tiny velocity (e.g. 1e-9 m/s, far below anything physical)
 * to the launch, in a seeded random direction. Contacts can make a catch-and-throw loop
 * sensitive to where it started: the spread of a throw's outcome across the copies, throw by
 * throw, bounds how much of that outcome a throw policy, which sees the state when THROW
 * starts, can choose. Engine-free: the copies are run elsewhere ({@link CatchEvaluation#run}).
 */
public final class LaunchSensitivity {

    /**
     * One throw's spread across the copies of an episode (or the mean over episodes).
     *
     * @param throwIndex the throw (1 = the first after the caught launch)
     * @param copies copies whose throw was measured (summed over episodes in a mean)
     * @param apexSd standard deviation of the apex height across the copies (m; NaN below 2 copies)
     * @param rotationSd ... of the flight rotation of the long axis (rad; NaN for an object without one)
     * @param rotationRange largest minus smallest flight rotation (rad; the mean of it over episodes)
     */
    public record Spread(int throwIndex, int copies, double apexSd, double rotationSd, double rotationRange) {
    }

    /**
     * One copy's headline figures, to set a figure's difference between two runs against what a
     * nudge alone does to it.
     *
     * @param copy the copy (0 = as seeded)
     * @param throwsMade throws after the caught launch
     * @param drops loops ending in a drop (0 or 1: a drop ends the copy)
     * @param heightAbsError mean |apex - target| over its throws (m; NaN without height targets)
     */
    public record CopyFigures(int copy, int throwsMade, int drops, double heightAbsError) {

        /** The figures of copy {@code copy}, whose loops are {@code loops}. */
        public static CopyFigures of(int copy, List<LoopRecord> loops) {
            return new CopyFigures(copy, (int) loops.stream().filter(l -> l.index() > 0).count(),
                    (int) loops.stream().filter(l -> !l.caught()).count(), HeightErrors.of(loops).absMean());
        }
    }

    private LaunchSensitivity() {
    }

    /** The launch nudges of the copies of an episode: none for copy 0, {@code size} m/s in random directions (from {@code seed}) for the rest. */
    public static List<Vec3> nudges(long seed, int copies, double size) {
        if (copies < 2 || !(size > 0)) {
            throw new IllegalArgumentException("a sensitivity needs at least 2 copies and a positive nudge, got " + copies + " and " + size);
        }
        Random rng = new Random(seed);
        List<Vec3> out = new ArrayList<>(List.of(Vec3.ZERO));
        while (out.size() < copies) {
            Vec3 d = new Vec3(rng.nextGaussian(), rng.nextGaussian(), rng.nextGaussian());
            if (d.norm() > 1e-6) {
                out.add(d.normalized().times(size));
            }
        }
        return out;
    }

    /** The spread of every throw (1, 2, ...) over the copies that made it and had it measured; {@code copies} holds each copy's loops. */
    public static List<Spread> spreads(List<List<LoopRecord>> copies) {
        int throwsMade = copies.stream().mapToInt(c -> c.size() - 1).max().orElse(0);
        List<Spread> out = new ArrayList<>();
        for (int k = 1; k <= throwsMade; k++) {
            List<Double> apex = new ArrayList<>(), rotation = new ArrayList<>();
            for (List<LoopRecord> c : copies) {
                if (k < c.size()) {
                    addFinite(apex, c.get(k).apexHeight());
                    addFinite(rotation, c.get(k).flightRotation());
                }
            }
            int n = Math.max(apex.size(), rotation.size());
            out.add(new Spread(k, n, sd(apex), sd(rotation), range(rotation)));
        }
        return out;
    }

    /** Spreads of several episodes, throw by throw: the mean of each episode's figure (episodes without it left out), copies summed. */
    public static List<Spread> mean(List<List<Spread>> episodes) {
        return summary(episodes, LaunchSensitivity::average);
    }

    /**
     * The same with the median of each episode's figure: the typical episode, where a few
     * episodes that jump (a can rolling the other way) dominate the mean.
     */
    public static List<Spread> median(List<List<Spread>> episodes) {
        return summary(episodes, LaunchSensitivity::middle);
    }

    private static List<Spread> summary(List<List<Spread>> episodes,
            java.util.function.ToDoubleFunction<List<Double>> statistic) {
        int throwsMade = episodes.stream().mapToInt(List::size).max().orElse(0);
        List<Spread> out = new ArrayList<>();
        for (int k = 1; k <= throwsMade; k++) {
            List<Double> apex = new ArrayList<>(), rotation = new ArrayList<>(), ranges = new ArrayList<>();
            int copies = 0;
            for (List<Spread> e : episodes) {
                if (k <= e.size()) {
                    Spread s = e.get(k - 1);
                    copies += s.copies();
                    addFinite(apex, s.apexSd());
                    addFinite(rotation, s.rotationSd());
                    addFinite(ranges, s.rotationRange());
                }
            }
            out.add(new Spread(k, copies, statistic.applyAsDouble(apex), statistic.applyAsDouble(rotation),
                    statistic.applyAsDouble(ranges)));
        }
        return out;
    }

    private static void addFinite(List<Double> to, double v) {
        if (Double.isFinite(v)) {
            to.add(v);
        }
    }

    static double average(List<Double> v) {
        return v.isEmpty() ? Double.NaN : v.stream().mapToDouble(Double::doubleValue).average().orElseThrow();
    }

    /** The median (NaN for none). */
    private static double middle(List<Double> v) {
        if (v.isEmpty()) {
            return Double.NaN;
        }
        double[] x = v.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        int n = x.length;
        return n % 2 == 1 ? x[n / 2] : (x[n / 2 - 1] + x[n / 2]) / 2;
    }

    /** Sample standard deviation (NaN below 2 values). */
    static double sd(List<Double> v) {
        if (v.size() < 2) {
            return Double.NaN;
        }
        double m = average(v), ss = 0;
        for (double x : v) {
            ss += (x - m) * (x - m);
        }
        return Math.sqrt(ss / (v.size() - 1));
    }

    private static double range(List<Double> v) {
        return v.size() < 2 ? Double.NaN
                : v.stream().mapToDouble(Double::doubleValue).max().orElseThrow() - v.stream().mapToDouble(Double::doubleValue).min().orElseThrow();
    }
}
