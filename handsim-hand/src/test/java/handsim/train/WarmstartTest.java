package handsim.train;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.config.Home;
import handsim.learn.DdpgAgent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The warm start's dataset and pretraining, without physics. */
@Tag("slow")
class WarmstartTest {

    private static List<Warmstart.Search> searches(int n, SplittableRandom r) {
        List<Warmstart.Search> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double[] s = new double[12], a = new double[7];
            for (int j = 0; j < s.length; j++) {
                s[j] = r.nextDouble() - 0.5;
            }
            for (int j = 0; j < a.length; j++) {
                a[j] = 0.8 * Math.tanh(s[j] + s[j + 1]);
            }
            double reward = i % 3 == 0 ? 0.2 : 1.5;
            out.add(new Warmstart.Search(i, 100 + i, s, a, reward, 150, reward >= 1));
        }
        return out;
    }

    @Test
    void theDatasetKeepsTheSuccessfulSearchesAndReadsBackExactly(@TempDir Path dir) throws Exception {
        List<Warmstart.Search> all = searches(30, new SplittableRandom(1));
        Warmstart.writeDataset(dir.resolve(Warmstart.DATASET), all);
        double[][][] data = Warmstart.readDataset(dir, 12, 7);
        List<Warmstart.Search> kept = all.stream().filter(Warmstart.Search::kept).toList();
        assertEquals(20, kept.size(), "one in three searches fell short of the keep reward");
        assertEquals(kept.size(), data[0].length);
        for (int i = 0; i < kept.size(); i++) {
            assertArrayEquals(kept.get(i).state(), data[0][i], 0, "states written with full precision");
            assertArrayEquals(kept.get(i).action(), data[1][i], 0);
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Warmstart.readDataset(dir, 13, 7));
        assertTrue(e.getMessage().contains("another task"), e.getMessage());
    }

    @Test
    void pretrainingIsDeterministicAndFitsTheExamples(@TempDir Path dir) throws Exception {
        Warmstart.writeDataset(dir.resolve(Warmstart.DATASET), searches(60, new SplittableRandom(2)));
        double[][][] data = Warmstart.readDataset(dir, 12, 7);
        TrainConfig c = TrainConfig.load(Home.resolve("configs/train/flip.json"));
        handsim.learn.ActorPretraining.Result[] r = new handsim.learn.ActorPretraining.Result[1];
        DdpgAgent a = Warmstart.pretrainedAgent(c, 12, 7, data, r), b = Warmstart.pretrainedAgent(c, 12, 7, data, null);
        for (double[] s : data[0]) {
            assertArrayEquals(a.act(s), b.act(s), 0, "same config, same data, same actor");
        }
        double[] v = r[0].validationLoss();
        // the held-out regression loss falls: the actor learns the examples' map, not just their mean
        assertTrue(v[v.length - 1] < 0.5 * v[0], "held-out loss " + v[0] + " -> " + v[v.length - 1]);
    }
}
