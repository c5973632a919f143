package handsim.learn;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.junit.jupiter.api.Test;

class RolloutsTest {

    @Test
    void batchesAreTheSameForAnyNumberOfWorkers() {
        TrainingConfig c = LearnTestSupport.config();
        Policy policy = PolicyTest.trainedAgent(4, 3, 31).policy("n", "a");
        List<Rollouts.Request> requests = new ArrayList<>();
        Rng seeds = new Rng(5);
        for (int i = 0; i < 12; i++) {
            requests.add(new Rollouts.Request(seeds.nextLong(), seeds.nextLong(), 0.2, i % 4 == 0, 6));
        }
        List<Rollouts.Episode> one = play(1, policy, requests, c);
        List<Rollouts.Episode> three = play(3, policy, requests, c);
        for (int i = 0; i < requests.size(); i++) {
            Rollouts.Episode e1 = one.get(i), e3 = three.get(i);
            assertEquals(requests.get(i), e1.request(), "results in request order");
            assertEquals(e1.transitions().size(), e3.transitions().size());
            assertEquals(e1.reward(), e3.reward(), 0.0);
            for (int t = 0; t < e1.transitions().size(); t++) {
                assertArrayEquals(e1.transitions().get(t).action(), e3.transitions().get(t).action(), 0.0);
                assertArrayEquals(e1.transitions().get(t).nextObs(), e3.transitions().get(t).nextObs(), 0.0);
            }
        }
    }

    @Test
    void parallelTrainingIsTheSameForAnyNumberOfWorkers() throws Exception {
        TrainingConfig c = LearnTestSupport.config("ddpg.batchSize", "16", "exploration.warmupSteps", "20",
                "training.episodes", "12", "training.parallelEpisodes", "4");
        assertEquals(statsOf(c, 1), statsOf(c, 2));
    }

    private static List<String> statsOf(TrainingConfig c, int workers) throws Exception {
        List<Env> envs = new ArrayList<>();
        for (int i = 0; i < workers; i++) {
            envs.add(new ToyEnvs.GoalReaching(5));
        }
        ExecutorService ex = Executors.newFixedThreadPool(workers);
        try {
            List<String> out = new ArrayList<>();
            Trainer.create(c, 4, 3).train(envs, ex, s -> out.add(MetricsCsv.row(s).replaceAll(",[^,]*$", "")), null);
            return out;
        } finally {
            ex.shutdownNow();
        }
    }

    private static List<Rollouts.Episode> play(int workers, Policy policy, List<Rollouts.Request> requests, TrainingConfig c) {
        List<Env> envs = new ArrayList<>();
        for (int i = 0; i < workers; i++) {
            envs.add(new ToyEnvs.GoalReaching(5));
        }
        ExecutorService ex = Executors.newFixedThreadPool(workers);
        try {
            return Rollouts.playAll(envs, ex, policy, requests, c.exploration());
        } finally {
            ex.shutdownNow();
        }
    }
}
