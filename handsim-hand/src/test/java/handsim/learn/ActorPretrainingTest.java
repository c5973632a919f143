package handsim.learn;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("slow")
class ActorPretrainingTest {

    @Test
    void regressionOnExamplesWarmStartsDdpg() throws Exception {
        // examples as CMA-ES would give them: for many goals, the best action (here known exactly)
        int n = 400;
        Rng rng = new Rng(8);
        double[][] obs = new double[n][], actions = new double[n][];
        for (int i = 0; i < n; i++) {
            obs[i] = new double[] {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
            actions[i] = ToyEnvs.GoalReaching.best(obs[i][0], obs[i][1]);
        }
        LearnerConfig c = LearnTestSupport.config("pretrain.epochs", "60", "pretrain.validationFraction", "0.25",
                "ddpg.batchSize", "8", "exploration.warmupSteps", "0", "exploration.sigma", "0.02", "training.episodes", "3");
        DdpgAgent agent = DdpgAgent.create(c.ddpg(), 4, 3, 1);
        long t0 = System.nanoTime();
        ActorPretraining.Result r = ActorPretraining.fit(agent, obs, actions, c.pretrain(), 2);
        double seconds = (System.nanoTime() - t0) * 1e-9;

        assertEquals(300, r.trainExamples());
        assertEquals(100, r.validationExamples());
        double first = r.validationLoss()[0], last = r.validationLoss()[r.validationLoss().length - 1];
        // the untrained actor outputs ~0, so the first loss is about the mean square of f (~0.1);
        // a 64-64 MLP fits this smooth map to a small fraction of that on unseen goals
        assertTrue(last < 0.05 * first, "held-out MSE " + first + " -> " + last);
        assertTrue(r.trainLoss()[r.trainLoss().length - 1] < 0.05 * r.trainLoss()[0]);

        double[] probe = {0.4, -0.3, 0.0, 0.9};
        assertArrayEquals(agent.act(probe), Networks.rowMajor(agent.actorTarget.output(
                Networks.matrix(agent.normalizer.normalize(probe), 1, 4), false)), 0.0, "target actor = actor");
        double reward = LearnTestSupport.meanReward(new ToyEnvs.GoalReaching(5), agent.policy("pretrained", ""), 40, 3);
        assertTrue(reward > 0.3, "pretrained policy reward " + reward + " (random actions get ~0.003)");
        System.out.printf("pretraining: held-out MSE %.4f -> %.5f in %.1f s, policy reward %.3f%n", first, last, seconds, reward);

        // DDPG starts from it
        Trainer t = Trainer.withAgent(c, agent);
        List<EpisodeStats> stats = new java.util.ArrayList<>();
        t.train(new ToyEnvs.GoalReaching(5), null, stats::add, null);
        assertEquals(3, stats.size());
        assertTrue(stats.get(0).reward() / 5 > 0.2, "the first episodes already use the pretrained actor: " + stats.get(0));
        assertTrue(t.agent().updates() > 0);
    }
}
