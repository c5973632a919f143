package handsim.cards.tpe;

import handsim.cards.study.Evaluation;
import handsim.cards.study.ParallelTrialsExperiment;
import handsim.cards.study.Study;
import handsim.cards.study.StudyConfig;
import handsim.cards.study.TrialRecord;
import handsim.config.Json;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.function.Function;
import java.util.stream.Stream;

/**
 * Independent against multivariate TPE (Optuna's {@code multivariate=False} / {@code True}), run
 * by scripts/sampler-comparison. Two modes:
 * <ul>
 * <li>{@code functions SEEDS TRIALS}: studies of two standard problems with each sampler over seeds
 * 1..S, the default settings (10 random start-up trials, 24 candidates, one trial at a time):
 * Hartmann's 6-D function (single objective, 6 parameters, as Card Snapping searches 6; the
 * regret of the best trial) and DTLZ2 with 3 objectives and 7 parameters (as Double Lift; Deb et
 * al. 2002; the hypervolume of the trials up to (1.1, 1.1, 1.1), whose largest possible value is
 * 1.1³ − π/6 = 0.8074). Prints a Markdown table of medians and means after n trials.</li>
 * <li>{@code studies DIR...}: a sleight study's folders, each named by its study.json (sampler,
 * seed): per study the best trial after n trials in units of the objectives' tolerances (the
 * largest objective over its tolerance; ≤ 1 meets the sleight), the first trial to meet the
 * tolerances, and for several objectives the hypervolume in tolerance units up to (5, 5, 5).</li>
 * </ul>
 */
public final class SamplerExperiment {

    private static final int[] NS = {10, 20, 25, 30, 50, 100, 150, 200};

    private SamplerExperiment() {
    }

    /** DTLZ2 with 3 objectives: x0, x1 place the point on the front (the unit sphere's octant), the rest g = Σ (x − ½)². */
    static double[] dtlz2(double[] x) {
        double g = 0;
        for (int i = 2; i < x.length; i++) {
            g += (x[i] - 0.5) * (x[i] - 0.5);
        }
        double a = 0.5 * Math.PI * x[0], b = 0.5 * Math.PI * x[1];
        return new double[] {(1 + g) * Math.cos(a) * Math.cos(b), (1 + g) * Math.cos(a) * Math.sin(b), (1 + g) * Math.sin(a)};
    }

    private static StudyConfig unitCube(String name, int objectives, int params, boolean multivariate) {
        StringBuilder o = new StringBuilder(), p = new StringBuilder();
        for (int i = 0; i < objectives; i++) {
            o.append(i == 0 ? "" : ",").append("{\"name\": \"f").append(i).append("\", \"direction\": \"minimize\"}");
        }
        for (int j = 0; j < params; j++) {
            p.append(j == 0 ? "" : ",").append("{\"name\": \"x").append(j).append("\", \"low\": 0, \"high\": 1}");
        }
        return StudyConfig.parse(Json.parse(name, "{\"objectives\": [" + o + "], \"params\": [" + p + "], \"parallelTrials\": 1,"
                + " \"sampler\": {\"multivariate\": " + multivariate + "}}"));
    }

    /** Each trial's objective values of one study of {@code f} over the unit cube. */
    private static List<double[]> run(String name, int objectives, int params, boolean multivariate, long seed, int trials,
            Function<double[], double[]> f, Path dir) throws IOException, InterruptedException {
        Study study = Study.openOrCreate(dir, unitCube(name, objectives, params, multivariate), seed, Json.mapper().createObjectNode());
        study.run(p -> {
            double[] x = new double[params];
            for (int j = 0; j < params; j++) {
                x[j] = p.get("x" + j);
            }
            return Evaluation.of(f.apply(x));
        }, trials, 1, null);
        return Study.open(dir).trials().stream().map(TrialRecord::values).toList();
    }

    /** The hypervolume of the first n value vectors, each clipped to the reference point (a clipped point adds nothing). */
    static double hypervolume(List<double[]> values, int n, double[] reference) {
        double[][] points = values.subList(0, Math.min(n, values.size())).stream().map(v -> clip(v, reference)).toArray(double[][]::new);
        return points.length == 0 ? 0 : Hypervolume.of(points, reference);
    }

    private static double[] clip(double[] v, double[] reference) {
        double[] c = new double[v.length];
        for (int d = 0; d < v.length; d++) {
            c[d] = Math.min(v[d], reference[d]);
        }
        return c;
    }

    private static void functions(int seeds, int trials) throws Exception {
        int[] ns = Arrays.stream(NS).filter(n -> n <= trials).toArray();
        Path tmp = Files.createTempDirectory("sampler-experiment");
        StringBuilder head = new StringBuilder("| problem | sampler |");
        for (int n : ns) {
            head.append(" after ").append(n).append(" (median / mean) |");
        }
        System.out.println(head);
        System.out.println("|---|---" + "|---".repeat(ns.length) + "|");
        double[] reference = {1.1, 1.1, 1.1};
        for (String problem : List.of("hartmann6 regret", "dtlz2 hypervolume")) {
            boolean regret = problem.startsWith("hartmann6");
            double[][][] at = new double[2][ns.length][seeds];
            for (int m = 0; m < 2; m++) {
                for (int s = 0; s < seeds; s++) {
                    Path dir = tmp.resolve(problem.split(" ")[0] + "-" + m + "-" + (s + 1));
                    if (regret) {
                        List<double[]> v = run("hartmann6", 1, 6, m == 1, s + 1, trials, x -> new double[] {ParallelTrialsExperiment.hartmann6(x)}, dir);
                        for (int k = 0; k < ns.length; k++) {
                            at[m][k][s] = v.subList(0, ns[k]).stream().mapToDouble(r -> r[0]).min().orElseThrow() - ParallelTrialsExperiment.MINIMUM;
                        }
                    } else {
                        List<double[]> v = run("dtlz2", 3, 7, m == 1, s + 1, trials, SamplerExperiment::dtlz2, dir);
                        for (int k = 0; k < ns.length; k++) {
                            at[m][k][s] = hypervolume(v, ns[k], reference);
                        }
                    }
                }
                StringBuilder row = new StringBuilder("| " + problem + " | " + (m == 1 ? "multivariate" : "independent") + " |");
                for (double[] a : at[m]) {
                    row.append(String.format(Locale.ROOT, " %.4f / %.4f |", median(a), Arrays.stream(a).average().orElseThrow()));
                }
                System.out.println(row);
            }
            // paired by seed (the same start-up trials): on how many seeds multivariate is ahead, behind
            StringBuilder row = new StringBuilder("| " + problem + " | multivariate ahead / behind (of " + seeds + " seeds) |");
            for (int k = 0; k < ns.length; k++) {
                int ahead = 0, behind = 0;
                for (int s = 0; s < seeds; s++) {
                    double better = regret ? at[0][k][s] - at[1][k][s] : at[1][k][s] - at[0][k][s];
                    ahead += better > 0 ? 1 : 0;
                    behind += better < 0 ? 1 : 0;
                }
                row.append(" ").append(ahead).append(" / ").append(behind).append(" |");
            }
            System.out.println(row);
        }
        try (Stream<Path> walk = Files.walk(tmp)) {
            walk.sorted(Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
        }
    }

    private static void studies(List<Path> dirs) throws IOException {
        System.out.println("| study | sampler | seed | trials | best after 10 / 20 / 30 / all (tolerances) | median of the TPE trials | first trial within |"
                + " hypervolume after 10 / 20 / 30 / all |");
        System.out.println("|---|---|---|---|---|---|---|---|");
        for (Path dir : dirs) {
            Study study = Study.open(dir);
            StudyConfig c = study.config();
            List<double[]> scaled = new ArrayList<>();
            int first = -1;
            for (TrialRecord t : study.trials()) {
                double[] s = t.isComplete() ? c.scaled(t.values()) : null;
                scaled.add(s);
                if (first < 0 && s != null && c.meets(t.values())) {
                    first = t.number();
                }
            }
            List<String> best = new ArrayList<>(), volume = new ArrayList<>();
            for (int n : new int[] {10, 20, 30, scaled.size()}) {
                if (n > scaled.size()) {
                    best.add("–");
                    volume.add("–");
                    continue;
                }
                List<double[]> done = scaled.subList(0, n).stream().filter(s -> s != null).toList();
                best.add(String.format(Locale.ROOT, "%.3g", done.stream().mapToDouble(s -> Arrays.stream(s).max().orElseThrow()).min().orElse(Double.NaN)));
                volume.add(c.multiObjective() ? String.format(Locale.ROOT, "%.2f", hypervolume(done, n, new double[] {5, 5, 5})) : "–");
            }
            // where the sampler put its trials after the random start-up: the median trial, in tolerances (a failed trial counts as infinite)
            double[] tpe = scaled.stream().skip(c.sampler().nStartupTrials())
                    .mapToDouble(v -> v == null ? Double.POSITIVE_INFINITY : Arrays.stream(v).max().orElseThrow()).toArray();
            System.out.printf(Locale.ROOT, "| %s | %s | %d | %d | %s | %s | %s | %s |%n", dir.getFileName(), c.sampler().multivariate() ? "multivariate" : "independent",
                    study.seed(), scaled.size(), String.join(" / ", best), tpe.length == 0 ? "–" : String.format(Locale.ROOT, "%.3g", median(tpe)),
                    first < 0 ? "none" : Integer.toString(first), String.join(" / ", volume));
        }
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        return ParallelTrialsExperiment.median(sorted);
    }

    public static void main(String[] args) throws Exception {
        if (args.length >= 3 && args[0].equals("functions")) {
            functions(Integer.parseInt(args[1]), Integer.parseInt(args[2]));
        } else if (args.length >= 2 && args[0].equals("studies")) {
            studies(Arrays.stream(args).skip(1).map(Path::of).toList());
        } else {
            System.err.println("usage: SamplerExperiment functions SEEDS TRIALS | studies DIR...");
            System.exit(2);
        }
    }
}
