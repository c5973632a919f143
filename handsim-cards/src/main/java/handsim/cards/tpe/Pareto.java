package handsim.cards.tpe;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Pareto dominance among loss vectors (every objective minimised): q dominates p when it is no
 * worse in every loss and better in one. Equal vectors do not dominate each other.
 */
public final class Pareto {

    private Pareto() {
    }

    /** The complete trials no other one dominates, in trial order. */
    public static List<CompletedTrial> front(List<CompletedTrial> trials, List<Direction> directions) {
        double[][] losses = losses(trials, directions);
        int[] rank = ranks(losses);
        List<CompletedTrial> front = new ArrayList<>();
        for (int i = 0; i < rank.length; i++) {
            if (rank[i] == 0) {
                front.add(trials.get(i));
            }
        }
        front.sort(java.util.Comparator.comparingInt(CompletedTrial::number));
        return front;
    }

    /**
     * Non-domination ranks: 0 for the front, 1 for the front of the rest, and so on (NSGA-II's
     * fast non-dominated sort, Deb et al. 2002).
     */
    static int[] ranks(double[][] losses) {
        int n = losses.length;
        int[] dominatedBy = new int[n];
        List<List<Integer>> dominated = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            dominated.add(new ArrayList<>());
        }
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                if (dominates(losses[j], losses[i])) {
                    dominatedBy[i]++;
                    dominated.get(j).add(i);
                }
            }
        }
        int[] rank = new int[n];
        Arrays.fill(rank, -1);
        int ranked = 0;
        for (int r = 0; ranked < n; r++) {
            List<Integer> front = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                if (rank[i] == -1 && dominatedBy[i] == 0) {
                    front.add(i);
                }
            }
            for (int i : front) {
                rank[i] = r;
                ranked++;
            }
            for (int i : front) {
                for (int k : dominated.get(i)) {
                    dominatedBy[k]--;
                }
            }
        }
        return rank;
    }

    static boolean dominates(double[] q, double[] p) {
        boolean better = false;
        for (int d = 0; d < q.length; d++) {
            if (q[d] > p[d]) {
                return false;
            }
            better |= q[d] < p[d];
        }
        return better;
    }

    /** Objective values as losses (maximised objectives change sign), one row per trial. */
    static double[][] losses(List<CompletedTrial> trials, List<Direction> directions) {
        double[][] losses = new double[trials.size()][directions.size()];
        for (int i = 0; i < losses.length; i++) {
            for (int d = 0; d < directions.size(); d++) {
                losses[i][d] = directions.get(d).loss(trials.get(i).value(d));
            }
        }
        return losses;
    }
}
