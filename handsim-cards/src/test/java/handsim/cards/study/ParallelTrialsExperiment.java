package handsim.cards.study;

import handsim.config.Json;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Comparator;
import java.util.Locale;
import java.util.stream.Stream;

/**
 * What parallel trials cost a TPE study in sample efficiency, on a cheap objective: studies of
 * Hartmann's 6-D function (6 parameters in [0, 1], as Card Snapping searches 6; minimum
 * -3.32237) with parallelTrials P = 1, 2, 4, 8 (or the list given), each over seeds 1..S, through {@link Study} and
 * its rule (trial k suggested from the trials numbered up to k - P). Prints, per P, the median
 * and mean regret (value - minimum) of the best trial after n trials, and how many trials the
 * median study needs to come within a regret. Run by scripts/tpe-parallel.
 *
 * <pre>java ... handsim.cards.study.ParallelTrialsExperiment SEEDS TRIALS [P,P,...]</pre>
 */
public final class ParallelTrialsExperiment {

    private static final double[][] A = {{10, 3, 17, 3.5, 1.7, 8}, {0.05, 10, 17, 0.1, 8, 14}, {3, 3.5, 1.7, 10, 17, 8},
        {17, 8, 0.05, 10, 0.1, 14}};
    private static final double[][] P = {{0.1312, 0.1696, 0.5569, 0.0124, 0.8283, 0.5886}, {0.2329, 0.4135, 0.8307, 0.3736, 0.1004, 0.9991},
        {0.2348, 0.1451, 0.3522, 0.2883, 0.3047, 0.6650}, {0.4047, 0.8828, 0.8732, 0.5743, 0.1091, 0.0381}};
    private static final double[] ALPHA = {1.0, 1.2, 3.0, 3.2};
    /** Hartmann 6's global minimum (Dixon and Szegö 1978; Surjanovic and Bingham's test-function library). */
    public static final double MINIMUM = -3.32237;

    private ParallelTrialsExperiment() {
    }

    public static double hartmann6(double[] x) {
        double f = 0;
        for (int i = 0; i < 4; i++) {
            double s = 0;
            for (int j = 0; j < 6; j++) {
                s += A[i][j] * (x[j] - P[i][j]) * (x[j] - P[i][j]);
            }
            f -= ALPHA[i] * Math.exp(-s);
        }
        return f;
    }

    private static StudyConfig config(int parallel) {
        StringBuilder params = new StringBuilder();
        for (int j = 0; j < 6; j++) {
            params.append(j == 0 ? "" : ",").append("{\"name\": \"x").append(j).append("\", \"low\": 0, \"high\": 1}");
        }
        return StudyConfig.parse(Json.parse("hartmann6", "{\"objectives\": [{\"name\": \"f\", \"direction\": \"minimize\"}], \"params\": ["
                + params + "], \"parallelTrials\": " + parallel + "}"));
    }

    /** The best value after each trial of one study. */
    static double[] bestSoFar(int parallel, long seed, int trials, Path dir) throws IOException, InterruptedException {
        Study study = Study.openOrCreate(dir, config(parallel), seed, Json.mapper().createObjectNode());
        study.run(p -> {
            double[] x = new double[6];
            for (int j = 0; j < 6; j++) {
                x[j] = p.get("x" + j);
            }
            return Evaluation.of(hartmann6(x));
        }, trials, 1, null);
        double[] best = new double[trials];
        double b = Double.POSITIVE_INFINITY;
        for (TrialRecord t : Study.open(dir).trials()) {
            b = Math.min(b, t.values()[0]);
            best[t.number()] = b;
        }
        return best;
    }

    public static void main(String[] args) throws Exception {
        int seeds = Integer.parseInt(args[0]);
        int trials = Integer.parseInt(args[1]);
        int[] batches = args.length > 2 ? Arrays.stream(args[2].split(",")).mapToInt(Integer::parseInt).toArray() : new int[] {1, 2, 4, 8};
        int[] ns = Arrays.stream(new int[] {10, 25, 50, 89, 150, 297}).filter(n -> n <= trials).toArray();
        double[] within = {1.0, 0.5, 0.25};
        Path tmp = Files.createTempDirectory("tpe-parallel");
        StringBuilder head = new StringBuilder("| P |");
        for (int n : ns) {
            head.append(" regret after ").append(n).append(" (median / mean) |");
        }
        for (double w : within) {
            head.append(" trials to regret ≤ ").append(w).append(" (median) |");
        }
        System.out.println(head);
        System.out.println("|---".repeat(1 + ns.length + within.length) + "|");
        for (int parallel : batches) {
            double[][] regret = new double[seeds][];
            for (int s = 0; s < seeds; s++) {
                double[] best = bestSoFar(parallel, s + 1, trials, tmp.resolve("p" + parallel + "-s" + (s + 1)));
                regret[s] = Arrays.stream(best).map(v -> v - MINIMUM).toArray();
            }
            StringBuilder row = new StringBuilder("| " + parallel + " |");
            for (int n : ns) {
                double[] at = Arrays.stream(regret).mapToDouble(r -> r[n - 1]).sorted().toArray();
                row.append(String.format(Locale.ROOT, " %.3f / %.3f |", median(at), Arrays.stream(at).average().orElseThrow()));
            }
            for (double w : within) {
                double[] need = Arrays.stream(regret).mapToDouble(r -> firstWithin(r, w)).sorted().toArray();
                double m = median(need);
                row.append(Double.isInfinite(m) ? String.format(Locale.ROOT, " > %d |", trials) : String.format(Locale.ROOT, " %.0f |", m));
            }
            System.out.println(row);
        }
        try (Stream<Path> walk = Files.walk(tmp)) {
            walk.sorted(Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
        }
    }

    /** The number of trials (1-based) after which the regret is within {@code w}, or infinity. */
    private static double firstWithin(double[] regret, double w) {
        for (int i = 0; i < regret.length; i++) {
            if (regret[i] <= w) {
                return i + 1;
            }
        }
        return Double.POSITIVE_INFINITY;
    }

    /** The median of values already sorted. */
    public static double median(double[] sorted) {
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    }
}
