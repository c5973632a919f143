package handsim.learn;

import handsim.report.Plot;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.function.ToDoubleFunction;

/**
 * PNG learning curves in the manner of paper Fig. 6, 9, 10: episode reward, moving-average
 * reward and "Episode Q0" against the episode; and the critic and actor losses.
 */
public final class LearningCurves {

    private LearningCurves() {
    }

    public static void plotRewards(Path png, List<EpisodeStats> stats, String title) throws IOException {
        double[] x = column(stats, s -> s.episode());
        new Plot(title, "episode", "reward")
                .add("episode reward", x, column(stats, EpisodeStats::reward), Plot.GREY, Plot.Style.POINTS)
                .add("average reward", x, column(stats, EpisodeStats::averageReward), Plot.BLUE, Plot.Style.LINE)
                .add("Episode Q0", x, column(stats, EpisodeStats::q0), Plot.ORANGE, Plot.Style.LINE)
                .writePng(png);
    }

    public static void plotLosses(Path png, List<EpisodeStats> stats, String title) throws IOException {
        double[] x = column(stats, s -> s.episode());
        new Plot(title, "episode", "loss (mean over the episode's updates)")
                .add("critic loss", x, column(stats, EpisodeStats::criticLoss), Plot.RED, Plot.Style.LINE)
                .add("actor loss, -Q", x, column(stats, EpisodeStats::actorLoss), Plot.GREEN, Plot.Style.LINE)
                .writePng(png);
    }

    private static double[] column(List<EpisodeStats> stats, ToDoubleFunction<EpisodeStats> f) {
        return stats.stream().mapToDouble(f).toArray();
    }

    /**
     * The first episode whose moving-average reward reaches {@code target}, or -1 if none does:
     * how the warm start's speed-up is read off two learning curves (paper Fig. 10).
     */
    public static long firstEpisodeReaching(List<EpisodeStats> stats, double target) {
        return stats.stream().filter(e -> e.averageReward() >= target).mapToLong(EpisodeStats::episode).findFirst().orElse(-1);
    }
}
