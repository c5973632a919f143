package handsim.app;

import handsim.learn.EpisodeStats;
import handsim.learn.LearningCurves;
import handsim.learn.MetricsCsv;
import handsim.report.Plot;
import handsim.train.TrainRun;
import java.awt.Color;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code handsim curves}: the learning curves of several training runs on one chart (for
 * example a flip run with and without the warm start, paper Fig. 10), with the episode at which
 * each run first reaches the first run's final average reward.
 */
@Command(name = "curves", mixinStandardHelpOptions = true,
        description = "Overlay the average-reward curves of training runs (their metrics.csv) in one PNG and print, for "
                + "each run, the first episode at which its average reward reaches the FIRST run's final average reward.")
final class CurvesCommand implements Callable<Integer> {

    private static final Color[] COLORS = {Plot.BLUE, Plot.ORANGE, Plot.GREEN, Plot.RED, Plot.GREY};

    @Parameters(arity = "1..5", paramLabel = "RUN_DIR", description = "run folders (the first one is the reference)")
    List<Path> runs;

    @Option(names = "--out", paramLabel = "FILE", required = true, description = "the PNG to write")
    Path out;

    @Option(names = "--title", description = "chart title (default: the runs' names)")
    String title;

    @Override
    public Integer call() throws Exception {
        runs.forEach(r -> OutputPaths.input(r.resolve(TrainRun.METRICS)));
        new OutputPaths().file("--out", out).check();
        List<List<EpisodeStats>> all = new ArrayList<>();
        for (Path r : runs) {
            Path metrics = r.resolve(TrainRun.METRICS);
            if (!Files.isRegularFile(metrics)) {
                throw new IllegalArgumentException(r + " is not a training run folder (no " + TrainRun.METRICS + ")");
            }
            List<EpisodeStats> s = MetricsCsv.read(metrics);
            if (s.isEmpty()) {
                throw new IllegalArgumentException(metrics + " has no episodes yet");
            }
            all.add(s);
        }
        double target = all.get(0).get(all.get(0).size() - 1).averageReward();
        Plot plot = new Plot(title != null ? title : "Average reward", "episode", "average episode reward");
        System.out.printf(Locale.ROOT, "reference: %s, final average reward %.3f after %d episodes%n", runs.get(0).getFileName(),
                target, all.get(0).size());
        for (int i = 0; i < all.size(); i++) {
            List<EpisodeStats> s = all.get(i);
            double[] x = s.stream().mapToDouble(EpisodeStats::episode).toArray();
            double[] y = s.stream().mapToDouble(EpisodeStats::averageReward).toArray();
            plot.add(RunFolders.withoutStartTime(runs.get(i)), x, y, COLORS[i % COLORS.length], Plot.Style.LINE);
            long reached = LearningCurves.firstEpisodeReaching(s, target);
            System.out.printf(Locale.ROOT, "%s: %d episodes, final average %.3f; reaches %.3f %s%n", runs.get(i).getFileName(),
                    s.size(), y[y.length - 1], target, reached < 0 ? "never" : "at episode " + reached);
        }
        plot.writePng(out);
        System.out.println("wrote " + out);
        return 0;
    }
}
