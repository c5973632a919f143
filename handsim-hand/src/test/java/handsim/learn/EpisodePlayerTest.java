package handsim.learn;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import handsim.rollout.LocalRollouts;
import handsim.rollout.Rollouts;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("fast")
class EpisodePlayerTest {

    @Test
    void batchesAreTheSameForAnyNumberOfWorkers() {
        LearnerConfig c = LearnTestSupport.config();
        Policy policy = PolicyTest.trainedAgent(4, 3, 31).policy("n", "a");
        List<EpisodePlayer.Request> requests = new ArrayList<>();
        Rng seeds = new Rng(5);
        for (int i = 0; i < 12; i++) {
            requests.add(new EpisodePlayer.Request(seeds.nextLong(), seeds.nextLong(), 0.2, i % 4 == 0, 6));
        }
        List<EpisodePlayer.Episode> one = play(1, policy, requests, c);
        List<EpisodePlayer.Episode> three = play(3, policy, requests, c);
        for (int i = 0; i < requests.size(); i++) {
            EpisodePlayer.Episode e1 = one.get(i), e3 = three.get(i);
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
        LearnerConfig c = LearnTestSupport.config("ddpg.batchSize", "16", "exploration.warmupSteps", "20",
                "training.episodes", "12", "training.parallelEpisodes", "4");
        assertEquals(statsOf(c, 1), statsOf(c, 2));
    }

    private static List<String> statsOf(LearnerConfig c, int workers) throws Exception {
        try (Rollouts<Env> envs = new LocalRollouts<>(workers, () -> new ToyEnvs.GoalReaching(5))) {
            List<String> out = new ArrayList<>();
            Trainer.create(c, 4, 3).train(null, EpisodePlayer.onWorkers(envs, c.exploration()),
                    s -> out.add(MetricsCsv.row(s).replaceAll(",[^,]*$", "")), null);
            return out;
        }
    }

    private static List<EpisodePlayer.Episode> play(int workers, Policy policy, List<EpisodePlayer.Request> requests, LearnerConfig c) {
        try (Rollouts<Env> envs = new LocalRollouts<>(workers, () -> new ToyEnvs.GoalReaching(5))) {
            return EpisodePlayer.playAll(envs, policy, requests, c.exploration());
        }
    }
}
