package handsim.learn;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.nd4j.linalg.api.ndarray.INDArray;
import org.nd4j.linalg.factory.Nd4j;

@Tag("slow")
class DdpgAgentTest {

    @Test
    void tdTargetBootstrapsUnlessTerminal() {
        DdpgAgent agent = PolicyTest.trainedAgent(3, 2, 11);
        double gamma = agent.config().gamma();
        double[] s = {0.1, 0.2, 0.3}, s2 = {-0.5, 0.4, 1.5}, a = {0.3, -0.2};
        ReplayBuffer.Batch b = new ReplayBuffer.Batch(2, concat(s, s), concat(a, a), new double[] {0.7, 0.7},
                concat(s2, s2), new boolean[] {true, false});
        double[] y = agent.tdTargets(b);
        // the target networks' own estimate at s', computed independently
        INDArray s2n = Networks.matrix(agent.normalizer.normalize(s2), 1, 3);
        double q2 = agent.criticTarget.output(Nd4j.hstack(s2n, agent.actorTarget.output(s2n, false)), false).getDouble(0);
        assertEquals(0.7, y[0], 0.0, "terminal: no bootstrap");
        assertEquals(0.7 + gamma * q2, y[1], 1e-12, "not terminal (a truncated step included): bootstrap from s'");
        assertTrue(Math.abs(q2) > 1e-4, "the check needs a target value away from 0, got " + q2);
    }

    @Test
    void criticInputGradientMatchesFiniteDifferences() {
        DdpgAgent agent = PolicyTest.trainedAgent(4, 3, 12);
        double[] x = {0.3, -0.2, 0.5, 0.1, 0.2, -0.4, 0.6};
        INDArray in = Networks.matrix(x, 1, 7);
        Networks.forwardForBackprop(agent.critic, in);
        double[] grad = Networks.rowMajor(Networks.inputGradient(agent.critic, Nd4j.ones(in.dataType(), 1, 1)));
        double h = 1e-6;
        for (int i = 0; i < 7; i++) {
            double[] xp = x.clone(), xm = x.clone();
            xp[i] += h;
            xm[i] -= h;
            double fd = (agent.critic.output(Networks.matrix(xp, 1, 7), false).getDouble(0)
                    - agent.critic.output(Networks.matrix(xm, 1, 7), false).getDouble(0)) / (2 * h);
            // central differences in double precision: error ~ h^2 f''' + eps / h, about 1e-9 here
            assertEquals(fd, grad[i], 1e-7, "dQ/dx_" + i);
        }
    }

    /**
     * A fresh agent started as another agent's policy snapshot acts as that agent (to round-off,
     * 1e-12: the same weights, the same arithmetic), and its target actor too. The snapshot's
     * normaliser statistics count as 10,000 observations, so one far-out observation moves an
     * action by less than 1e-2 (the normalised input moves by about 1/10,000 of its offset). A
     * snapshot of another shape is refused, naming the layer.
     */
    @Test
    void anActorStartedAsAPolicyActsAsThePolicy() {
        DdpgAgent trained = PolicyTest.trainedAgent(5, 2, 31);
        Policy snapshot = trained.policy("teacher", "[-1, 1]^2");
        DdpgAgent fresh = DdpgAgent.create(trained.config(), 5, 2, 32);
        fresh.startActorFrom(snapshot, 10_000);
        Rng rng = new Rng(33);
        for (int i = 0; i < 10; i++) {
            double[] s = PolicyTest.gaussian(rng, 5, 3);
            assertArrayEquals(trained.act(s), fresh.act(s), 1e-12, "observation " + i);
            INDArray sn = Networks.matrix(fresh.normalizer.normalize(s), 1, 5);
            assertArrayEquals(fresh.act(s), Networks.rowMajor(fresh.actorTarget.output(sn, false)), 1e-12, "target actor");
        }
        double[] probe = {0.5, -0.3, 1.0, 0.2, -1.1}, before = fresh.act(probe);
        fresh.observe(new double[] {30, -30, 30, -30, 30});
        double[] after = fresh.act(probe);
        for (int k = 0; k < 2; k++) {
            assertEquals(before[k], after[k], 1e-2, "action " + k + " after one far-out observation");
        }
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> DdpgAgent.create(trained.config(), 6, 2, 34).startActorFrom(snapshot, 10_000));
        assertTrue(e.getMessage().contains("layer 0"), e.getMessage());
    }

    @Test
    void sameSeedSameDataSameNetworks() {
        double[] p1 = params(PolicyTest.trainedAgent(6, 2, 21));
        double[] p2 = params(PolicyTest.trainedAgent(6, 2, 21));
        double[] p3 = params(PolicyTest.trainedAgent(6, 2, 22));
        assertArrayEquals(p1, p2, 0.0);
        assertFalse(Arrays.equals(p1, p3));
    }

    @Test
    void updatesMoveTargetsSlowly() {
        DdpgAgent agent = PolicyTest.trainedAgent(3, 1, 13);
        double[] before = Networks.rowMajor(agent.actorTarget.params());
        double[] net = Networks.rowMajor(agent.actor.params());
        agent.update();
        double[] netAfter = Networks.rowMajor(agent.actor.params());
        double[] after = Networks.rowMajor(agent.actorTarget.params());
        double tau = agent.config().tau();
        for (int i = 0; i < before.length; i += 7) {
            assertEquals((1 - tau) * before[i] + tau * netAfter[i], after[i], 1e-12);
        }
        assertFalse(Arrays.equals(net, netAfter), "the actor moved");
    }

    @Test
    void criticWarmupLeavesTheActorAsItIs() {
        DdpgAgent agent = PolicyTest.trainedAgent(3, 1, 14);
        double[] actor = Networks.rowMajor(agent.actor.params());
        double[] actorTarget = Networks.rowMajor(agent.actorTarget.params());
        double[] critic = Networks.rowMajor(agent.critic.params());
        DdpgAgent.Losses losses = agent.update(false);
        // exactly unchanged: no gradient step and no soft update touched the actor or its target
        assertArrayEquals(actor, Networks.rowMajor(agent.actor.params()), 0.0);
        assertArrayEquals(actorTarget, Networks.rowMajor(agent.actorTarget.params()), 0.0);
        assertFalse(Arrays.equals(critic, Networks.rowMajor(agent.critic.params())), "the critic learned");
        assertTrue(Double.isFinite(losses.actor()) && Double.isFinite(losses.critic()), "both losses still reported");
    }

    @Test
    void optionalL2AndClippingReachTheNetworks() {
        LearnerConfig.Ddpg c = LearnTestSupport.config("ddpg.criticL2", "0.01", "ddpg.gradientClip", "5",
                "ddpg.actorHidden", "[32]").ddpg();
        DdpgAgent agent = DdpgAgent.create(c, 3, 2, 1);
        var criticLayer = (org.deeplearning4j.nn.conf.layers.BaseLayer) agent.critic.getLayerWiseConfigurations()
                .getConf(0).getLayer();
        var actorLayer = (org.deeplearning4j.nn.conf.layers.BaseLayer) agent.actor.getLayerWiseConfigurations()
                .getConf(0).getLayer();
        assertEquals(org.deeplearning4j.nn.conf.GradientNormalization.ClipL2PerLayer, criticLayer.getGradientNormalization());
        assertEquals(5.0, criticLayer.getGradientNormalizationThreshold(), 0.0);
        assertEquals(1, criticLayer.getRegularization().size(), "L2 on the critic's weights");
        assertTrue(actorLayer.getRegularization().isEmpty(), "actorL2 = 0: none on the actor");
        assertEquals(2, agent.actor.getnLayers(), "one hidden layer of 32, then the output");
        assertEquals(32, agent.actor.layerSize(0));
    }

    /** A TD3 agent (batch 16) with the given td3 block, after {@link PolicyTest#trainedAgent}'s 20 updates. */
    private static DdpgAgent td3Agent(String td3, long seed) {
        return PolicyTest.trainedAgent(LearnTestSupport.config("ddpg.batchSize", "16", "ddpg.td3", td3).ddpg(), 3, 2, seed);
    }

    @Test
    void twinCriticsBootstrapFromTheSmallerTargetEstimate() {
        DdpgAgent agent = td3Agent("{\"twinCritics\": true, \"policyDelay\": 1, \"targetNoise\": 0, \"targetNoiseClip\": 0.5}", 15);
        double gamma = agent.config().gamma();
        Rng rng = new Rng(3);
        int n = 8;
        double[] s2 = new double[3 * n];
        for (int i = 0; i < s2.length; i++) {
            s2[i] = 1 + 3 * rng.nextGaussian();
        }
        ReplayBuffer.Batch b = new ReplayBuffer.Batch(n, new double[3 * n], new double[2 * n], new double[n], s2, new boolean[n]);
        double[] y = agent.tdTargets(b);
        // both target critics at (s', mu'(s')), computed independently: y takes the smaller (TD3, eq. 15)
        INDArray s2n = Networks.matrix(agent.normalizer.normalize(s2), n, 3);
        INDArray in = Nd4j.hstack(s2n, agent.actorTarget.output(s2n, false));
        double[] q1s = Networks.rowMajor(agent.criticTarget.output(in, false));
        double[] q2s = Networks.rowMajor(agent.critic2Target.output(in, false));
        int fromSecond = 0;
        for (int i = 0; i < n; i++) {
            double q1 = q1s[i], q2 = q2s[i];
            assertEquals(gamma * Math.min(q1, q2), y[i], 1e-12, "row " + i);
            fromSecond += q2 < q1 ? 1 : 0;
        }
        // two independently initialised critics disagree: some rows must come from each, or the check checks nothing
        assertTrue(fromSecond > 0 && fromSecond < n, fromSecond + " of " + n + " targets from the second critic");
    }

    @Test
    void delayedPolicyUpdatesMoveTheActorAndTargetsEveryOtherUpdate() {
        DdpgAgent agent = td3Agent("{\"twinCritics\": true, \"policyDelay\": 2, \"targetNoise\": 0.2, \"targetNoiseClip\": 0.5}", 16);
        assertEquals(20, agent.updates(), "trainedAgent made an even number of updates: the next one is not a policy step");
        double[] actor = Networks.rowMajor(agent.actor.params());
        double[] targets = targetParams(agent);
        double[] critics = concat(Networks.rowMajor(agent.critic.params()), Networks.rowMajor(agent.critic2.params()));
        agent.update(); // update 21 (index 20, even): the actor and the targets learn
        assertFalse(Arrays.equals(actor, Networks.rowMajor(agent.actor.params())), "policy step: the actor moved");
        double[] actor2 = Networks.rowMajor(agent.actor.params());
        double[] targets2 = targetParams(agent);
        assertFalse(Arrays.equals(targets, targets2), "policy step: the targets moved");
        agent.update(); // index 21, odd: only the two critics learn
        assertArrayEquals(actor2, Networks.rowMajor(agent.actor.params()), 0.0, "no policy step: the actor stays");
        assertArrayEquals(targets2, targetParams(agent), 0.0, "no policy step: the targets stay");
        double[] critics3 = concat(Networks.rowMajor(agent.critic.params()), Networks.rowMajor(agent.critic2.params()));
        assertFalse(Arrays.equals(critics, critics3), "the critics learn on every update");
    }

    @Test
    void targetPolicyNoiseIsClipped() {
        String noisy = "{\"twinCritics\": false, \"policyDelay\": 1, \"targetNoise\": 0.3, \"targetNoiseClip\": %s}";
        double[] s2 = {0.4, -1.2, 2.0, 1.5, 0.3, -0.7};
        ReplayBuffer.Batch b = new ReplayBuffer.Batch(2, new double[6], new double[4], new double[2], s2, new boolean[2]);
        // clipped to 0 the noise vanishes: the targets are DDPG's gamma Q'(s', mu'(s')) (rewards 0 here)
        DdpgAgent clippedAway = td3Agent(String.format(noisy, "0"), 17);
        assertArrayEquals(noiselessTargets(clippedAway, s2), clippedAway.tdTargets(b), 1e-12);
        DdpgAgent withNoise = td3Agent(String.format(noisy, "0.5"), 17);
        double[] clean = noiselessTargets(withNoise, s2), y = withNoise.tdTargets(b);
        assertTrue(Math.abs(clean[0] - y[0]) > 1e-9 || Math.abs(clean[1] - y[1]) > 1e-9,
                "noise up to 0.5 of the action range changes the targets");
    }

    /** The parameters of a TD3 agent's three target networks, one after the other. */
    private static double[] targetParams(DdpgAgent agent) {
        return concat(Networks.rowMajor(agent.actorTarget.params()),
                concat(Networks.rowMajor(agent.criticTarget.params()), Networks.rowMajor(agent.critic2Target.params())));
    }

    /** gamma Q'(s', mu'(s')) for each row of {@code s2}, from the target networks directly. */
    private static double[] noiselessTargets(DdpgAgent agent, double[] s2) {
        int n = s2.length / agent.observationSize();
        INDArray s2n = Networks.matrix(agent.normalizer.normalize(s2), n, agent.observationSize());
        INDArray q = agent.criticTarget.output(Nd4j.hstack(s2n, agent.actorTarget.output(s2n, false)), false);
        double[] y = Networks.rowMajor(q);
        for (int i = 0; i < n; i++) {
            y[i] *= agent.config().gamma();
        }
        return y;
    }

    private static double[] params(DdpgAgent a) {
        return concat(concat(Networks.rowMajor(a.actor.params()), Networks.rowMajor(a.critic.params())),
                concat(Networks.rowMajor(a.actorTarget.params()), Networks.rowMajor(a.criticTarget.params())));
    }

    static double[] concat(double[] a, double[] b) {
        double[] c = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, c, a.length, b.length);
        return c;
    }
}
