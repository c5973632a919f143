package handsim.cards.tpe;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;

/**
 * Hypervolumes of loss vectors (all objectives minimised) up to a reference point, and the
 * greedy hypervolume subset selection MOTPE uses (Ozaki et al. 2020), following Optuna
 * 3.6.1's {@code optuna._hypervolume}: a sweep in two dimensions, the WFG algorithm (While,
 * Bradstreet and Barone 2012) in more.
 */
final class Hypervolume {

    private Hypervolume() {
    }

    /** The volume dominated by the points and bounded by the reference point (every point <= it). */
    static double of(double[][] points, double[] reference) {
        for (double[] p : points) {
            for (int d = 0; d < p.length; d++) {
                if (!(p[d] <= reference[d])) {
                    throw new IllegalArgumentException("point " + Arrays.toString(p) + " is not dominated by the reference point " + Arrays.toString(reference));
                }
            }
        }
        return reference.length == 2 ? sweep2d(points, reference) : wfg(points, reference);
    }

    /** Two objectives: strips between consecutive points sorted by the first loss (then the second, descending). */
    private static double sweep2d(double[][] points, double[] reference) {
        double[][] sorted = points.clone();
        Arrays.sort(sorted, Comparator.<double[]>comparingDouble(p -> p[0]).thenComparingDouble(p -> -p[1]));
        double volume = 0, top = reference[1];
        for (double[] p : sorted) {
            if (top < p[1]) {
                continue;
            }
            volume += Math.abs((reference[0] - p[0]) * (top - p[1]));
            top = p[1];
        }
        return volume;
    }

    /** WFG: the sum over points, sorted by the first loss, of each one's volume exclusive of the points after it. */
    private static double wfg(double[][] points, double[] reference) {
        int n = points.length;
        if (n == 0) {
            return 0;
        }
        if (n == 1) {
            return box(points[0], reference);
        }
        if (n == 2) {
            double overlap = 1;
            for (int d = 0; d < reference.length; d++) {
                overlap *= reference[d] - Math.max(points[0][d], points[1][d]);
            }
            return box(points[0], reference) + box(points[1], reference) - overlap;
        }
        double[][] sorted = points.clone();
        Arrays.sort(sorted, Comparator.comparingDouble(p -> p[0]));
        double volume = 0;
        for (int i = 0; i < n; i++) {
            volume += exclusive(sorted[i], Arrays.copyOfRange(sorted, i + 1, n), reference);
        }
        return volume;
    }

    private static double exclusive(double[] point, double[][] others, double[] reference) {
        double[][] limited = limit(point, others);
        double volume = box(point, reference);
        if (limited.length == 1) {
            volume -= box(limited[0], reference);
        } else if (limited.length > 1) {
            volume -= wfg(limited, reference);
        }
        return volume;
    }

    /**
     * The others pushed back to where they overlap the point's box (max per loss), keeping,
     * in a left-to-right scan, only those not dominated by the last kept one (WFG's "limit set",
     * as Optuna thins it).
     */
    private static double[][] limit(double[] point, double[][] others) {
        double[][] limited = new double[others.length][];
        for (int i = 0; i < others.length; i++) {
            limited[i] = new double[point.length];
            for (int d = 0; d < point.length; d++) {
                limited[i][d] = Math.max(others[i][d], point[d]);
            }
        }
        if (limited.length <= 1) {
            return limited;
        }
        List<double[]> kept = new ArrayList<>();
        kept.add(limited[0]);
        int left = 0;
        for (int right = 1; right < limited.length; right++) {
            if (anyGreater(limited[left], limited[right])) {
                left = right;
                kept.add(limited[left]);
            }
        }
        return kept.toArray(double[][]::new);
    }

    private static boolean anyGreater(double[] p, double[] q) {
        for (int d = 0; d < p.length; d++) {
            if (p[d] > q[d]) {
                return true;
            }
        }
        return false;
    }

    private static double box(double[] p, double[] reference) {
        double v = 1;
        for (int d = 0; d < p.length; d++) {
            v *= p[d] - reference[d];
        }
        return Math.abs(v);
    }

    /**
     * Greedy hypervolume subset selection (Guerreiro et al. 2016), Optuna 3.6.1's
     * {@code _solve_hssp}: repeatedly takes the point of largest remaining contribution (first
     * on ties). Returns positions into {@code points}, in the order taken.
     */
    static int[] greedySubset(double[][] points, int size, double[] reference) {
        double[] contribution = new double[points.length];
        for (int i = 0; i < points.length; i++) {
            contribution[i] = of(new double[][] {points[i]}, reference);
        }
        List<double[]> selected = new ArrayList<>();
        int[] taken = new int[size];
        double selectedVolume = 0;
        for (int s = 0; s < size; s++) {
            int best = 0;
            for (int i = 1; i < points.length; i++) {
                if (contribution[i] > contribution[best]) {
                    best = i;
                }
            }
            contribution[best] = -1; // taken
            for (int j = 0; j < points.length; j++) {
                if (contribution[j] == -1) {
                    continue;
                }
                // what point j adds beyond the taken ones, its box cut down to the one just taken
                double[] overlap = new double[reference.length];
                for (int d = 0; d < overlap.length; d++) {
                    overlap[d] = Math.max(points[best][d], points[j][d]);
                }
                List<double[]> with = new ArrayList<>(selected);
                with.add(overlap);
                contribution[j] -= of(with.toArray(double[][]::new), reference) - selectedVolume;
            }
            selected.add(points[best]);
            taken[s] = best;
            selectedVolume = of(selected.toArray(double[][]::new), reference);
        }
        return taken;
    }
}
