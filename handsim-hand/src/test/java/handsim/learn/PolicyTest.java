package handsim.learn;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.config.ConfigException;
import handsim.config.Json;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

@Tag("slow")
class PolicyTest {

    /** An agent whose actor has moved off its initialisation and whose normaliser has statistics. */
    static DdpgAgent trainedAgent(int obsSize, int actionSize, long seed) {
        return trainedAgent(LearnTestSupport.config("ddpg.batchSize", "16").ddpg(), obsSize, actionSize, seed);
    }

    /** An agent of config {@code c} after 20 updates on 64 random transitions. */
    static DdpgAgent trainedAgent(LearnerConfig.Ddpg c, int obsSize, int actionSize, long seed) {
        DdpgAgent agent = DdpgAgent.create(c, obsSize, actionSize, seed);
        Rng rng = new Rng(seed);
        for (int i = 0; i < 64; i++) {
            double[] s = gaussian(rng, obsSize, 3), s2 = gaussian(rng, obsSize, 3), a = gaussian(rng, actionSize, 0.5);
            agent.observe(s);
            agent.store(s, clip(a), rng.nextDouble(), s2, false);
        }
        for (int i = 0; i < 20; i++) {
            agent.update();
        }
        return agent;
    }

    static double[] gaussian(Rng rng, int n, double scale) {
        double[] x = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = 1 + scale * rng.nextGaussian();
        }
        return x;
    }

    private static double[] clip(double[] a) {
        for (int i = 0; i < a.length; i++) {
            a[i] = Normalizer.clip(a[i], 1);
        }
        return a;
    }

    @Test
    void plainForwardEqualsTheDl4jActor() {
        DdpgAgent agent = trainedAgent(16, 7, 5);
        Policy p = agent.policy("test", "[-1, 1]^7");
        Rng rng = new Rng(9);
        double worst = 0;
        for (int i = 0; i < 50; i++) {
            double[] obs = gaussian(rng, 16, 10); // some entries beyond the normaliser's clip
            double[] nd4j = agent.act(obs), plain = p.act(obs);
            for (int j = 0; j < 7; j++) {
                worst = Math.max(worst, Math.abs(nd4j[j] - plain[j]));
            }
        }
        // both evaluate the same double-precision arithmetic, only the summation order differs
        assertTrue(worst < 1e-6, "largest difference " + worst);
    }

    @Test
    void fileRoundTripGivesIdenticalActions(@TempDir Path dir) throws Exception {
        Policy p = trainedAgent(5, 2, 6).policy("toy, seed 6", "[-1, 1]^2 onto the toy's box");
        Path file = dir.resolve("policy.json");
        p.save(file);
        Policy q = Policy.load(file);
        assertEquals(p.note(), q.note());
        assertEquals(p.actionSpace(), q.actionSpace());
        Rng rng = new Rng(1);
        for (int i = 0; i < 20; i++) {
            double[] obs = gaussian(rng, 5, 2);
            assertArrayEquals(p.act(obs), q.act(obs), 0.0, "doubles are written in round-trip form");
        }
        String text = Files.readString(file);
        assertTrue(text.contains("\"format\" : \"handsim-policy\"") && text.contains("\"activation\" : \"tanh\""), text);
    }

    @Test
    void malformedFilesNameTheField() {
        var node = trainedAgent(3, 1, 2).policy("n", "a").toJson();
        ((com.fasterxml.jackson.databind.node.ArrayNode) node.get("layers").get(1).get("bias")).add(0.5);
        ConfigException e = assertThrows(ConfigException.class, () -> Policy.parse(Json.of("p.json", node)));
        assertTrue(e.getMessage().contains("layers[1].bias"), e.getMessage());
    }

    @Test
    void concurrentCallsAgree() throws Exception {
        Policy p = trainedAgent(8, 3, 3).policy("n", "a");
        double[] obs = gaussian(new Rng(4), 8, 1);
        double[] expected = p.act(obs);
        ExecutorService ex = Executors.newFixedThreadPool(4);
        try {
            List<Future<double[]>> fs = new ArrayList<>();
            for (int i = 0; i < 200; i++) {
                fs.add(ex.submit(() -> p.act(obs)));
            }
            for (Future<double[]> f : fs) {
                assertArrayEquals(expected, f.get(), 0.0);
            }
        } finally {
            ex.shutdownNow();
        }
    }
}
