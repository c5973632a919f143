package handsim.evaluation;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;

/**
 * Two flip evaluations compared episode by episode on the seeds they share: the loops in a row of
 * controller B minus those of A, seed by seed. Two controllers that differ in a detail play a
 * seed's episode alike up to the first moment the detail matters, so most episodes come out the
 * same: the paired difference judges them far more sharply than the two means, whose standard
 * errors over 40 episodes are about 7 loops each (docs/experiments.md).
 *
 * @param seeds the seeds both evaluations ran, ascending
 * @param meanA mean loops in a row of A on those seeds
 * @param meanB the same for B
 * @param standardError the standard error of {@link #meanDifference} (the differences' sample
 *     standard deviation over the square root of their number; NaN for a single seed)
 * @param changes the seeds where B's loops differ from A's, ascending
 * @param onlyA seeds A ran and B did not
 * @param onlyB seeds B ran and A did not
 */
public record PairedLoops(List<Long> seeds, double meanA, double meanB, double standardError,
        List<Change> changes, List<Long> onlyA, List<Long> onlyB) {

    /** One seed whose loops differ. */
    public record Change(long seed, int loopsA, int loopsB) {
    }

    /** Compares the loops in a row by seed of A and of B; fails when they share no seed (the caller names the two). */
    public static PairedLoops of(Map<Long, Integer> a, Map<Long, Integer> b) {
        List<Long> seeds = new ArrayList<>(new TreeSet<>(a.keySet()));
        seeds.retainAll(b.keySet());
        if (seeds.isEmpty()) {
            throw new IllegalArgumentException("the two evaluations share no seed");
        }
        double sumA = 0, sumB = 0, sumD = 0, sumD2 = 0;
        List<Change> changes = new ArrayList<>();
        for (long s : seeds) {
            int la = a.get(s), lb = b.get(s);
            sumA += la;
            sumB += lb;
            sumD += lb - la;
            sumD2 += (double) (lb - la) * (lb - la);
            if (la != lb) {
                changes.add(new Change(s, la, lb));
            }
        }
        int n = seeds.size();
        double mean = sumD / n;
        double variance = n > 1 ? Math.max(0, (sumD2 - n * mean * mean) / (n - 1)) : Double.NaN;
        List<Long> onlyA = new ArrayList<>(new TreeSet<>(a.keySet()));
        onlyA.removeAll(b.keySet());
        List<Long> onlyB = new ArrayList<>(new TreeSet<>(b.keySet()));
        onlyB.removeAll(a.keySet());
        return new PairedLoops(List.copyOf(seeds), sumA / n, sumB / n, Math.sqrt(variance / n), List.copyOf(changes),
                List.copyOf(onlyA), List.copyOf(onlyB));
    }

    /** The mean of B − A over the shared seeds. */
    public double meanDifference() {
        return meanB - meanA;
    }

    /** Seeds where B made more loops than A. */
    public long better() {
        return changes.stream().filter(c -> c.loopsB() > c.loopsA()).count();
    }

    /** Seeds where B made fewer loops than A. */
    public long worse() {
        return changes.size() - better();
    }
}
