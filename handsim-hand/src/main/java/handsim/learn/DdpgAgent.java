package handsim.learn;

import java.util.ArrayList;
import java.util.List;
import org.deeplearning4j.nn.multilayer.MultiLayerNetwork;
import org.nd4j.linalg.activations.Activation;
import org.nd4j.linalg.api.ndarray.INDArray;
import org.nd4j.linalg.factory.Nd4j;
import org.nd4j.linalg.indexing.NDArrayIndex;
import org.nd4j.linalg.ops.transforms.Transforms;

/**
 * Deep deterministic policy gradient (Lillicrap et al. 2015, Alg. 1), the learner of paper
 * sec. 3.7: an actor mu(s) in [-1, 1]^k (tanh output), a critic Q(s, a) (linear output, input
 * the observation and action side by side), slowly tracking target copies of both, a replay
 * buffer and an observation normaliser; optionally with TD3's twin critics, delayed policy
 * updates and target policy smoothing ({@link LearnerConfig.Td3}). Not thread-safe: one
 * training thread owns the agent; rollout workers use {@link #policy} snapshots.
 */
public final class DdpgAgent {

    /** Losses of one update: critic mean squared TD error and actor loss, mean -Q(s, mu(s)). */
    public record Losses(double critic, double actor) {
    }

    final LearnerConfig.Ddpg config;
    final int obsSize;
    final int actionSize;
    final MultiLayerNetwork actor;
    final MultiLayerNetwork critic;
    final MultiLayerNetwork actorTarget;
    final MultiLayerNetwork criticTarget;
    /** TD3's second critic and its target ({@code td3.twinCritics}), else null. */
    final MultiLayerNetwork critic2;
    final MultiLayerNetwork critic2Target;
    final Normalizer normalizer;
    final ReplayBuffer replay;
    final Rng replayRng;
    long updates;

    /**
     * A fresh agent: random networks, targets equal to them, empty replay and statistics.
     * Seeding: {@code seed} starts a generator whose first draw seeds the actor's weight
     * initialisation, the second the critic's, the third the replay sampling (and TD3's target
     * noise), the fourth TD3's second critic.
     */
    public static DdpgAgent create(LearnerConfig.Ddpg c, int obsSize, int actionSize, long seed) {
        Rng seeds = new Rng(seed);
        MultiLayerNetwork actor = Networks.mlp(obsSize, c.actorHidden(), actionSize, Activation.TANH, c.actorLr(),
                c.actorL2(), c, seeds.nextLong());
        MultiLayerNetwork critic = critic(c, obsSize, actionSize, seeds.nextLong());
        Rng replayRng = new Rng(seeds.nextLong());
        MultiLayerNetwork critic2 = c.td3().twinCritics() ? critic(c, obsSize, actionSize, seeds.nextLong()) : null;
        return new DdpgAgent(c, obsSize, actionSize, actor, critic, actor.clone(), critic.clone(), critic2,
                critic2 == null ? null : critic2.clone(),
                new Normalizer(obsSize, c.normalizeObservations(), c.observationClip(), c.observationMinStd()),
                new ReplayBuffer(c.replayCapacity(), obsSize, actionSize), replayRng);
    }

    private static MultiLayerNetwork critic(LearnerConfig.Ddpg c, int obsSize, int actionSize, long seed) {
        return Networks.mlp(obsSize + actionSize, c.criticHidden(), 1, Activation.IDENTITY, c.criticLr(), c.criticL2(),
                c, seed);
    }

    /** All parts given ({@link #create}, checkpoint loading). */
    DdpgAgent(LearnerConfig.Ddpg config, int obsSize, int actionSize, MultiLayerNetwork actor, MultiLayerNetwork critic,
            MultiLayerNetwork actorTarget, MultiLayerNetwork criticTarget, MultiLayerNetwork critic2,
            MultiLayerNetwork critic2Target, Normalizer normalizer, ReplayBuffer replay, Rng replayRng) {
        if ((critic2 != null) != config.td3().twinCritics() || (critic2 == null) != (critic2Target == null)) {
            throw new IllegalArgumentException("td3.twinCritics is " + config.td3().twinCritics()
                    + " but the second critic and its target are " + (critic2 == null ? "absent" : "present"));
        }
        this.config = config;
        this.obsSize = obsSize;
        this.actionSize = actionSize;
        this.actor = actor;
        this.critic = critic;
        this.actorTarget = actorTarget;
        this.criticTarget = criticTarget;
        this.critic2 = critic2;
        this.critic2Target = critic2Target;
        this.normalizer = normalizer;
        this.replay = replay;
        this.replayRng = replayRng;
    }

    // ---- acting ---------------------------------------------------------------------------

    public int observationSize() {
        return obsSize;
    }

    public int actionSize() {
        return actionSize;
    }

    public LearnerConfig.Ddpg config() {
        return config;
    }

    /** Gradient updates done so far. */
    public long updates() {
        return updates;
    }

    public int replaySize() {
        return replay.size();
    }

    /** The actor's deterministic action mu(s) for one raw observation. */
    public double[] act(double[] obs) {
        return Networks.rowMajor(actor.output(normalized(obs, 1), false));
    }

    /** The critic's estimate Q(s, a) for one raw observation and action. */
    public double q(double[] obs, double[] action) {
        INDArray s = normalized(obs, 1);
        return critic.output(Nd4j.hstack(s, Networks.matrix(action, 1, actionSize)), false).getDouble(0);
    }

    /** Q(s, mu(s)): "Episode Q0" when s is an episode's first observation (paper Fig. 6). */
    public double value(double[] obs) {
        return q(obs, act(obs));
    }

    /** Adds an observation to the normaliser's running statistics. */
    public void observe(double[] obs) {
        normalizer.observe(obs);
    }

    /** Stores a transition; {@code terminal} only for real ends, not for truncations. */
    public void store(double[] obs, double[] action, double reward, double[] nextObs, boolean terminal) {
        replay.add(obs, action, reward, nextObs, terminal);
    }

    /** The actor as a plain-Java snapshot, with the normaliser's current statistics. */
    public Policy policy(String note, String actionSpace) {
        List<Policy.Layer> layers = new ArrayList<>();
        for (var layer : actor.getLayers()) {
            double[][] wt = layer.getParam("W").transpose().toDoubleMatrix(); // DL4J keeps W as [in, out]
            double[] b = Networks.rowMajor(layer.getParam("b"));
            String act = ((org.deeplearning4j.nn.conf.layers.BaseLayer) layer.conf().getLayer()).getActivationFn().toString();
            layers.add(new Policy.Layer(wt, b, switch (act) {
                case "relu" -> Policy.Activation.RELU;
                case "tanh" -> Policy.Activation.TANH;
                case "identity" -> Policy.Activation.IDENTITY;
                default -> throw new IllegalStateException("unexpected activation " + act);
            }));
        }
        boolean norm = normalizer.enabled();
        return new Policy(norm ? normalizer.mean() : null, norm ? normalizer.std() : null, normalizer.clip(), layers,
                note, actionSpace);
    }

    /**
     * Starts the actor, and its target, as a saved policy: its layers' weights, and the
     * normaliser's statistics as if from {@code observations} observations (so the first ones DDPG
     * adds barely move the inputs the actor was trained on). For fine-tuning a trained actor; the
     * critic stays fresh. The policy must have this actor's sizes, activations and normalisation.
     */
    public void startActorFrom(Policy p, long observations) {
        var mine = policy("", "");
        if (p.layers().size() != mine.layers().size()) {
            throw new IllegalArgumentException("the policy has " + p.layers().size() + " layers, the actor "
                    + mine.layers().size() + " (ddpg.actorHidden)");
        }
        for (int i = 0; i < p.layers().size(); i++) {
            Policy.Layer theirs = p.layers().get(i), ours = mine.layers().get(i);
            if (theirs.inputs() != ours.inputs() || theirs.outputs() != ours.outputs()
                    || theirs.activation() != ours.activation()) {
                throw new IllegalArgumentException("the policy's layer " + i + " is " + theirs.inputs() + " -> "
                        + theirs.outputs() + " " + theirs.activation() + ", the actor's " + ours.inputs() + " -> "
                        + ours.outputs() + " " + ours.activation());
            }
        }
        if ((p.mean() != null) != normalizer.enabled() || p.mean() != null && p.clip() != normalizer.clip()) {
            throw new IllegalArgumentException("the policy's observation normalisation (" + (p.mean() != null ? "clip " + p.clip() : "none")
                    + ") is not the actor's (ddpg.normalizeObservations, ddpg.observationClip)");
        }
        if (observations < 2) {
            throw new IllegalArgumentException("the policy's statistics must count as at least 2 observations, got " + observations);
        }
        for (int i = 0; i < p.layers().size(); i++) {
            var layer = actor.getLayer(i);
            layer.setParam("W", Nd4j.create(p.layers().get(i).weights()).transpose().dup()); // DL4J keeps W as [in, out]
            layer.setParam("b", Networks.matrix(p.layers().get(i).bias(), 1, p.layers().get(i).outputs()));
        }
        actorTarget.params().assign(actor.params());
        if (p.mean() != null) {
            double[] m2 = p.std();
            for (int i = 0; i < m2.length; i++) {
                m2[i] = m2[i] * m2[i] * observations; // Welford's sum of squares for this std
            }
            normalizer.restore(p.mean(), m2, observations);
        }
    }

    // ---- learning -------------------------------------------------------------------------

    /** Whether the replay buffer holds enough transitions for a batch. */
    public boolean canUpdate() {
        return replay.size() >= config.batchSize();
    }

    /**
     * One DDPG update on a batch drawn from the replay buffer (Alg. 1, inner loop); with TD3's
     * {@code policyDelay} d, the actor and the targets learn on every d-th update only.
     */
    public Losses update() {
        return update(true);
    }

    /**
     * One update; with {@code updateActor} false only the critic (and its target) learns and
     * the actor stays as it is: the critic warm-up that lets a pretrained actor's critic catch
     * up before the actor follows its gradient.
     */
    public Losses update(boolean updateActor) {
        ReplayBuffer.Batch b = replay.sample(config.batchSize(), replayRng);
        int n = b.size();
        INDArray s = normalized(b.obs(), n);
        INDArray a = Networks.matrix(b.actions(), n, actionSize);
        INDArray y = Networks.matrix(tdTargets(b), n, 1);

        // critic (and TD3's second): minimise mean (Q(s, a) - y)^2
        INDArray sa = Nd4j.hstack(s, a);
        double criticLoss = descendTdError(critic, sa, y);
        if (critic2 != null) {
            descendTdError(critic2, sa, y);
        }

        boolean delayedStep = updates % config.td3().policyDelay() == 0;
        double actorLoss;
        if (updateActor && delayedStep) {
            // actor: maximise Q(s, mu(s)), following dQ/da back through the actor (deterministic policy gradient)
            INDArray mu = Networks.forwardForBackprop(actor, s);
            INDArray qMu = Networks.forwardForBackprop(critic, Nd4j.hstack(s, mu));
            actorLoss = -qMu.meanNumber().doubleValue();
            INDArray dLossDInput = Networks.inputGradient(critic, Nd4j.ones(qMu.dataType(), n, 1).negi());
            INDArray dLossDAction = dLossDInput.get(NDArrayIndex.all(), NDArrayIndex.interval(obsSize, obsSize + actionSize)).dup();
            Networks.descend(actor, dLossDAction);
            Networks.softUpdate(actorTarget, actor, config.tau());
        } else {
            actorLoss = -critic.output(Nd4j.hstack(s, actor.output(s, false)), false).meanNumber().doubleValue();
        }
        if (delayedStep) {
            Networks.softUpdate(criticTarget, critic, config.tau());
            if (critic2 != null) {
                Networks.softUpdate(critic2Target, critic2, config.tau());
            }
        }
        updates++;
        return new Losses(criticLoss, actorLoss);
    }

    /** One step of {@code net} on mean (net(input) - y)^2; returns that loss before the step. */
    private static double descendTdError(MultiLayerNetwork net, INDArray input, INDArray y) {
        INDArray err = Networks.forwardForBackprop(net, input).sub(y);
        double loss = err.mul(err).meanNumber().doubleValue();
        Networks.descend(net, err.muli(2));
        return loss;
    }

    /**
     * TD targets y = r + gamma (1 - terminal) Q'(s', mu'(s')) with the target networks. A
     * truncated step is not terminal: it bootstraps from s' like any other. With TD3, mu'(s')
     * gets clipped Gaussian noise (then clipped to [-1, 1]) and Q' is the smaller of the two
     * target critics (Fujimoto et al. 2018, eq. 14-15).
     */
    double[] tdTargets(ReplayBuffer.Batch b) {
        int n = b.size();
        INDArray s2 = normalized(b.nextObs(), n);
        INDArray a2 = actorTarget.output(s2, false);
        LearnerConfig.Td3 td3 = config.td3();
        if (td3.targetNoise() > 0) {
            double[] noisy = Networks.rowMajor(a2);
            for (int i = 0; i < noisy.length; i++) {
                double eps = Normalizer.clip(td3.targetNoise() * replayRng.nextGaussian(), td3.targetNoiseClip());
                noisy[i] = Normalizer.clip(noisy[i] + eps, 1);
            }
            a2 = Networks.matrix(noisy, n, actionSize);
        }
        INDArray s2a2 = Nd4j.hstack(s2, a2);
        INDArray q2 = criticTarget.output(s2a2, false);
        if (critic2Target != null) {
            q2 = Transforms.min(q2, critic2Target.output(s2a2, false));
        }
        double[] y = new double[n];
        for (int i = 0; i < n; i++) {
            y[i] = b.rewards()[i] + (b.terminal()[i] ? 0 : config.gamma() * q2.getDouble(i, 0));
        }
        return y;
    }

    private INDArray normalized(double[] rowsOfObs, int rows) {
        if (rowsOfObs.length != rows * obsSize) {
            throw new IllegalArgumentException("observation has " + rowsOfObs.length / rows + " entries, expected " + obsSize);
        }
        return Networks.matrix(normalizer.normalize(rowsOfObs), rows, obsSize);
    }
}
