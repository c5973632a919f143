package handsim.cards.tpe;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * TPE's split of the finished trials into the "below" (good) ones that l(x) is fitted to and
 * the "above" ones for g(x), and MOTPE's weights of the good ones; Optuna 3.6.1's
 * {@code _split_trials} and {@code _calculate_weights_below_for_multi_objective}.
 *
 * <p>One objective: the nBelow trials of best value (ties in trial order). Several
 * (MOTPE, Ozaki et al. 2020): whole non-domination ranks while they fit, then the last rank's
 * points chosen by greedy hypervolume subset selection. Both lists come back in trial order.
 */
final class TrialSplit {

    /** Optuna's floor for reference-point coordinates that come out 0, and for contributions. */
    private static final double EPS = 1e-12;

    record Split(List<CompletedTrial> below, List<CompletedTrial> above) {
    }

    private TrialSplit() {
    }

    static Split split(List<CompletedTrial> trials, List<Direction> directions, int nBelow) {
        List<CompletedTrial> byNumber = new ArrayList<>(trials);
        byNumber.sort(Comparator.comparingInt(CompletedTrial::number));
        int n = Math.min(nBelow, byNumber.size());
        boolean[] isBelow = directions.size() == 1 ? bestValues(byNumber, directions.get(0), n) : paretoSelection(byNumber, directions, n);
        List<CompletedTrial> below = new ArrayList<>(), above = new ArrayList<>();
        for (int i = 0; i < byNumber.size(); i++) {
            (isBelow[i] ? below : above).add(byNumber.get(i));
        }
        return new Split(below, above);
    }

    /** The n trials of best value; a stable sort keeps ties in trial order. */
    private static boolean[] bestValues(List<CompletedTrial> trials, Direction direction, int n) {
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < trials.size(); i++) {
            order.add(i);
        }
        order.sort(Comparator.comparingDouble(i -> direction.loss(trials.get(i).value(0))));
        boolean[] below = new boolean[trials.size()];
        for (int k = 0; k < n; k++) {
            below[order.get(k)] = true;
        }
        return below;
    }

    /** Whole non-domination ranks while they fit in n, then a hypervolume-greedy subset of the next. */
    private static boolean[] paretoSelection(List<CompletedTrial> trials, List<Direction> directions, int n) {
        boolean[] below = new boolean[trials.size()];
        if (n == 0) {
            return below;
        }
        double[][] losses = Pareto.losses(trials, directions);
        int[] rank = Pareto.ranks(losses);
        int taken = 0, r = 0;
        for (; taken < n && taken + count(rank, r) <= n; r++) {
            for (int i = 0; i < rank.length; i++) {
                if (rank[i] == r) {
                    below[i] = true;
                    taken++;
                }
            }
        }
        if (taken < n) {
            List<Integer> members = new ArrayList<>();
            for (int i = 0; i < rank.length; i++) {
                if (rank[i] == r) {
                    members.add(i);
                }
            }
            double[][] front = members.stream().map(i -> losses[i]).toArray(double[][]::new);
            for (int k : Hypervolume.greedySubset(front, n - taken, referencePoint(front))) {
                below[members.get(k)] = true;
            }
        }
        return below;
    }

    /**
     * MOTPE's weights of the good trials (in the given order): each one's hypervolume
     * contribution (+1e-12) over the largest; a single trial weighs 1.
     */
    static double[] hypervolumeWeights(List<CompletedTrial> below, List<Direction> directions) {
        int n = below.size();
        if (n <= 1) {
            return n == 0 ? new double[0] : new double[] {1.0};
        }
        double[][] losses = Pareto.losses(below, directions);
        double[] reference = referencePoint(losses);
        double total = Hypervolume.of(losses, reference);
        double[] contribution = new double[n];
        double max = 0;
        for (int i = 0; i < n; i++) {
            double[][] others = new double[n - 1][];
            for (int j = 0, k = 0; j < n; j++) {
                if (j != i) {
                    others[k++] = losses[j];
                }
            }
            contribution[i] = total - Hypervolume.of(others, reference) + EPS;
            max = Math.max(max, contribution[i]);
        }
        for (int i = 0; i < n; i++) {
            contribution[i] = Math.min(Math.max(contribution[i] / max, 0), 1);
        }
        return contribution;
    }

    private static int count(int[] rank, int r) {
        int c = 0;
        for (int x : rank) {
            c += x == r ? 1 : 0;
        }
        return c;
    }

    /** Optuna's reference point: the worst loss per objective pushed 10 % outward; 0 becomes 1e-12. */
    private static double[] referencePoint(double[][] losses) {
        double[] reference = new double[losses[0].length];
        for (int d = 0; d < reference.length; d++) {
            double worst = Double.NEGATIVE_INFINITY;
            for (double[] l : losses) {
                worst = Math.max(worst, l[d]);
            }
            reference[d] = Math.max(1.1 * worst, 0.9 * worst);
            if (reference[d] == 0) {
                reference[d] = EPS;
            }
        }
        return reference;
    }
}
