package handsim.learn;

import org.deeplearning4j.nn.multilayer.MultiLayerNetwork;
import org.nd4j.linalg.api.ndarray.INDArray;

/**
 * The imitation warm start of paper sec. 4.4: the actor of a fresh {@link DdpgAgent} is fitted
 * by regression (mean squared error) to examples (observation, action in [-1, 1]^k), e.g. the
 * CMA-ES throws for many initial conditions; part of the examples is held out to measure
 * generalisation. Afterwards the target actor is set equal to the actor and the actor's Adam
 * state is reset, so DDPG starts from the pretrained policy with a fresh optimiser.
 */
public final class ActorPretraining {

    /** Mean squared error per action entry, per epoch (validation: NaN if nothing held out). */
    public record Result(double[] trainLoss, double[] validationLoss, int trainExamples, int validationExamples) {
    }

    private ActorPretraining() {
    }

    /**
     * Fits the agent's actor. The normaliser's statistics are first fed the training
     * observations, so the actor is fitted on the inputs it will see in DDPG. {@code seed}
     * fixes the split and the minibatch order.
     */
    public static Result fit(DdpgAgent agent, double[][] observations, double[][] actions, LearnerConfig.Pretrain config,
            long seed) {
        return fit(agent, observations, actions, null, config, seed);
    }

    /**
     * {@link #fit} with a weight per example (null: all 1): the training loss is the weighted sum
     * of squared errors, so an example of weight 2 pulls as two copies of it would (the
     * validation loss stays unweighted).
     */
    public static Result fit(DdpgAgent agent, double[][] observations, double[][] actions, double[] weights,
            LearnerConfig.Pretrain config, long seed) {
        int n = observations.length, obsSize = agent.observationSize(), k = agent.actionSize();
        if (weights != null && weights.length != n) {
            throw new IllegalArgumentException("need one weight per example, got " + weights.length + " for " + n);
        }
        if (actions.length != n || n < 2) {
            throw new IllegalArgumentException("need at least 2 examples and as many actions as observations, got "
                    + n + " and " + actions.length);
        }
        for (int i = 0; i < n; i++) {
            if (observations[i].length != obsSize || actions[i].length != k) {
                throw new IllegalArgumentException("example " + i + " has sizes " + observations[i].length + "/"
                        + actions[i].length + ", expected " + obsSize + "/" + k);
            }
            for (double a : actions[i]) {
                if (!(a >= -1 && a <= 1)) {
                    throw new IllegalArgumentException("example " + i + ": actions must be in [-1, 1], got " + a);
                }
            }
        }
        // split: a seeded shuffle, the first part held out
        Rng rng = new Rng(seed);
        int[] order = permutation(n, rng);
        int nVal = (int) Math.round(config.validationFraction() * n);
        int nTrain = n - nVal;
        int[] train = java.util.Arrays.copyOfRange(order, nVal, n);
        int[] val = java.util.Arrays.copyOfRange(order, 0, nVal);
        for (int i : train) {
            agent.observe(observations[i]);
        }

        MultiLayerNetwork actor = agent.actor;
        actor.setLearningRate(config.learningRate());
        double[] trainLoss = new double[config.epochs()];
        double[] valLoss = new double[config.epochs()];
        for (int epoch = 0; epoch < config.epochs(); epoch++) {
            shuffle(train, rng);
            double sum = 0;
            for (int start = 0; start < nTrain; start += config.batchSize()) {
                int[] idx = java.util.Arrays.copyOfRange(train, start, Math.min(nTrain, start + config.batchSize()));
                INDArray out = Networks.forwardForBackprop(actor, inputs(agent, observations, idx));
                INDArray err = out.sub(Networks.matrix(rows(actions, idx, k), idx.length, k));
                INDArray weighted = weights == null ? err : err.mulColumnVector(Networks.matrix(pick(weights, idx), idx.length, 1));
                sum += err.mul(weighted).sumNumber().doubleValue();
                Networks.descend(actor, weighted.muli(2)); // d/da of the (weighted) summed squared error
            }
            trainLoss[epoch] = sum / ((double) nTrain * k);
            valLoss[epoch] = nVal == 0 ? Double.NaN : loss(agent, observations, actions, val);
        }
        actor.setLearningRate(agent.config().actorLr());
        actor.getUpdater().getStateViewArray().assign(0);
        actor.setIterationCount(0);
        agent.actorTarget.params().assign(actor.params());
        return new Result(trainLoss, valLoss, nTrain, nVal);
    }

    /** Mean squared error per action entry of the agent's actor on the given examples. */
    static double loss(DdpgAgent agent, double[][] observations, double[][] actions, int[] idx) {
        INDArray out = agent.actor.output(inputs(agent, observations, idx), false);
        INDArray err = out.sub(Networks.matrix(rows(actions, idx, agent.actionSize()), idx.length, agent.actionSize()));
        return err.mul(err).meanNumber().doubleValue();
    }

    private static INDArray inputs(DdpgAgent agent, double[][] observations, int[] idx) {
        double[] x = agent.normalizer.normalize(rows(observations, idx, agent.observationSize()));
        return Networks.matrix(x, idx.length, agent.observationSize());
    }

    private static double[] rows(double[][] data, int[] idx, int width) {
        double[] out = new double[idx.length * width];
        for (int r = 0; r < idx.length; r++) {
            System.arraycopy(data[idx[r]], 0, out, r * width, width);
        }
        return out;
    }

    private static double[] pick(double[] values, int[] idx) {
        double[] out = new double[idx.length];
        for (int r = 0; r < idx.length; r++) {
            out[r] = values[idx[r]];
        }
        return out;
    }

    private static int[] permutation(int n, Rng rng) {
        int[] p = new int[n];
        for (int i = 0; i < n; i++) {
            p[i] = i;
        }
        shuffle(p, rng);
        return p;
    }

    private static void shuffle(int[] a, Rng rng) {
        for (int i = a.length - 1; i > 0; i--) {
            int j = rng.nextInt(i + 1);
            int t = a[i];
            a[i] = a[j];
            a[j] = t;
        }
    }
}
