package handsim.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

@Tag("fast")
class MetricsCsvTest {

    private static EpisodeStats stats(long episode) {
        return new EpisodeStats(episode, 5 * episode, 5, 0.25 * episode, 0.1, episode == 1 ? Double.NaN : -0.5, Double.NaN,
                Double.NaN, 0, episode % 2 == 0, Double.NaN, 0.125 * episode);
    }

    @Test
    void rowsRoundTripAndAResumeDropsEpisodesAfterTheCheckpoint(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("metrics.csv");
        try (MetricsCsv csv = MetricsCsv.open(file, 0)) {
            for (long e = 1; e <= 5; e++) {
                csv.onEpisode(stats(e));
            }
        }
        assertEquals(List.of(stats(1), stats(2), stats(3), stats(4), stats(5)), MetricsCsv.read(file));
        try (MetricsCsv csv = MetricsCsv.open(file, 3)) { // checkpoint after episode 3, episodes 4-5 are replayed
            csv.onEpisode(stats(4));
        }
        assertEquals(List.of(stats(1), stats(2), stats(3), stats(4)), MetricsCsv.read(file));

        Path png = dir.resolve("rewards.png");
        LearningCurves.plotRewards(png, MetricsCsv.read(file), "toy");
        LearningCurves.plotLosses(dir.resolve("losses.png"), MetricsCsv.read(file), "toy");
        assertTrue(Files.size(png) > 1000 && Files.size(dir.resolve("losses.png")) > 1000);
    }

    @Test
    void theFirstEpisodeReachingATargetAverageIsFoundOrMinusOne() {
        // average rewards 0.1, 0.3, 0.6, 0.5: 0.5 is first reached at episode 3, 10 never
        double[] averages = {0.1, 0.3, 0.6, 0.5};
        List<EpisodeStats> s = new java.util.ArrayList<>();
        for (int e = 1; e <= averages.length; e++) {
            s.add(new EpisodeStats(e, e, 1, averages[e - 1], averages[e - 1], Double.NaN, Double.NaN, Double.NaN, 0, false,
                    Double.NaN, 0.0));
        }
        assertEquals(3, LearningCurves.firstEpisodeReaching(s, 0.5));
        assertEquals(-1, LearningCurves.firstEpisodeReaching(s, 10));
    }
}
