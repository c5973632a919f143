package handsim.learn;

import com.fasterxml.jackson.annotation.JsonValue;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Every hyper-parameter of learning, read from one JSON file (default
 * {@code configs/train/ddpg-defaults.json}, fields documented in {@code configs/train/README.md}).
 * Nothing has a default in code: a missing field is an error that names it.
 *
 * @param seed the root seed; every generator of a run (weight init, replay sampling, episode and
 *     noise seeds) is derived from it ({@link DdpgAgent}, {@link Trainer})
 */
public record LearnerConfig(long seed, Ddpg ddpg, Exploration exploration, Training training, Pretrain pretrain,
        Cmaes cmaes) {

    public static LearnerConfig load(Path file) {
        return parse(Json.load(file));
    }

    public static LearnerConfig parse(Json j) {
        j.allow("comment");
        LearnerConfig c = new LearnerConfig(j.longValue("seed"), Ddpg.parse(j.get("ddpg")),
                Exploration.parse(j.get("exploration")), Training.parse(j.get("training")),
                Pretrain.parse(j.get("pretrain")), Cmaes.parse(j.get("cmaes")));
        j.requireNoUnknownFields();
        return c;
    }

    /**
     * This configuration in the file's format: {@code parse(toJson())} gives it back. Plain DDPG
     * writes no {@code td3} block, as its config files have none, and an unset
     * {@code pretrain.policyObservations} is left out.
     */
    public ObjectNode toJson() {
        ObjectNode node = Json.mapper().valueToTree(this);
        if (ddpg.td3().equals(Td3.OFF)) {
            ((ObjectNode) node.get("ddpg")).remove("td3");
        }
        if (pretrain.policyObservations() == 0) {
            ((ObjectNode) node.get("pretrain")).remove("policyObservations"); // not set, as in the files that leave it out
        }
        return node;
    }

    public LearnerConfig withSeed(long newSeed) {
        return new LearnerConfig(newSeed, ddpg, exploration, training, pretrain, cmaes);
    }

    /**
     * The DDPG learner (Lillicrap et al. 2015, sec. 7 "experiment details" for the usual values).
     *
     * @param actorHidden hidden layer widths of the actor (ReLU); paper sec. 3.7: 64, 64
     * @param criticHidden hidden layer widths of the critic (ReLU); its input is (observation, action)
     * @param finalLayerInit final layers start uniform in [-x, x] so first actions and values are near 0
     * @param actorLr Adam learning rate of the actor
     * @param criticLr Adam learning rate of the critic
     * @param adamBeta1 Adam first-moment decay
     * @param adamBeta2 Adam second-moment decay
     * @param adamEpsilon Adam epsilon
     * @param actorL2 L2 weight penalty of the actor (0 = none)
     * @param criticL2 L2 weight penalty of the critic (0 = none)
     * @param gradientClip largest L2 norm of a layer's gradient (0 = no clipping)
     * @param gamma discount per decision
     * @param tau soft target update rate: target = tau * net + (1 - tau) * target
     * @param batchSize transitions per update
     * @param replayCapacity transitions kept (oldest overwritten)
     * @param normalizeObservations whether observations are standardised by running statistics
     * @param observationClip normalised observations are clipped to [-clip, clip]
     * @param observationMinStd floor of the running standard deviation
     */
    public record Ddpg(List<Integer> actorHidden, List<Integer> criticHidden, double finalLayerInit, double actorLr, double criticLr,
            double adamBeta1, double adamBeta2, double adamEpsilon, double actorL2, double criticL2,
            double gradientClip, double gamma, double tau, int batchSize, int replayCapacity,
            boolean normalizeObservations, double observationClip, double observationMinStd, Td3 td3) {

        public Ddpg {
            actorHidden = List.copyOf(actorHidden);
            criticHidden = List.copyOf(criticHidden);
        }

        static Ddpg parse(Json j) {
            j.allow("comment");
            Ddpg d = new Ddpg(widths(j, "actorHidden"), widths(j, "criticHidden"),
                    j.number("finalLayerInit", 1e-9, 1), j.positive("actorLr"), j.positive("criticLr"),
                    j.number("adamBeta1", 0, 0.999999), j.number("adamBeta2", 0, 0.999999999),
                    j.number("adamEpsilon", 1e-16, 1), j.number("actorL2", 0, 10), j.number("criticL2", 0, 10),
                    j.number("gradientClip", 0, 1e9), j.number("gamma", 0, 1), j.number("tau", 1e-9, 1),
                    j.integer("batchSize", 1, 1 << 16), j.integer("replayCapacity", 1, 100_000_000),
                    requiredBool(j, "normalizeObservations"), j.number("observationClip", 1e-3, 1e6),
                    j.number("observationMinStd", 1e-12, 1e6), j.has("td3") ? Td3.parse(j.get("td3")) : Td3.OFF);
            if (d.replayCapacity < d.batchSize) {
                throw j.fieldError("replayCapacity", "must be >= batchSize (" + d.batchSize + "), got " + d.replayCapacity);
            }
            j.requireNoUnknownFields();
            return d;
        }
    }

    /**
     * TD3's three changes to DDPG (Fujimoto, van Hoof and Meger 2018, "Addressing function
     * approximation error in actor-critic methods", Alg. 1), each off by default; a config
     * without a {@code td3} block is plain DDPG.
     *
     * @param twinCritics two critics learn the same TD targets, and the targets take the smaller
     *     of their two target networks' estimates (clipped double Q-learning)
     * @param policyDelay the actor and all target networks learn on one update in this many
     *     (delayed policy updates; 1 = every update, as DDPG)
     * @param targetNoise standard deviation of the Gaussian noise added to the target actor's
     *     action in the TD target, in units of the [-1, 1] action range (target policy smoothing)
     * @param targetNoiseClip that noise is clipped to plus or minus this
     */
    public record Td3(boolean twinCritics, int policyDelay, double targetNoise, double targetNoiseClip) {

        /** Plain DDPG. */
        public static final Td3 OFF = new Td3(false, 1, 0, 0);

        static Td3 parse(Json j) {
            j.allow("comment");
            Td3 t = new Td3(requiredBool(j, "twinCritics"), j.integer("policyDelay", 1, 1000),
                    j.number("targetNoise", 0, 10), j.number("targetNoiseClip", 0, 10));
            j.requireNoUnknownFields();
            return t;
        }
    }

    /** Kinds of exploration noise added to the actor's action. */
    public enum NoiseType {
        GAUSSIAN, OU;

        /** The name used in config files. */
        @JsonValue
        public String configName() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    /**
     * Exploration: random actions first, then the actor's action plus noise, clipped to [-1, 1].
     *
     * @param warmupSteps decisions taken uniformly at random before the actor acts (and before
     *     the first update)
     * @param noise "gaussian" (independent per decision) or "ou" (Ornstein-Uhlenbeck, DDPG paper,
     *     correlated over the decisions of an episode)
     * @param sigma noise standard deviation at the start
     * @param sigmaFinal noise standard deviation after the decay
     * @param sigmaDecaySteps decisions over which sigma falls linearly to sigmaFinal (0 = no decay)
     * @param ouTheta OU mean reversion per decision, x += -theta x + sigma N(0, 1)
     */
    public record Exploration(int warmupSteps, NoiseType noise, double sigma, double sigmaFinal, int sigmaDecaySteps,
            double ouTheta) {

        static Exploration parse(Json j) {
            j.allow("comment");
            Exploration e = new Exploration(j.integer("warmupSteps", 0, Integer.MAX_VALUE),
                    NoiseType.valueOf(j.choice("noise", "gaussian", "ou").toUpperCase(Locale.ROOT)),
                    j.number("sigma", 0, 10), j.number("sigmaFinal", 0, 10),
                    j.integer("sigmaDecaySteps", 0, Integer.MAX_VALUE), j.number("ouTheta", 0, 1));
            j.requireNoUnknownFields();
            return e;
        }

        /** The noise scale after {@code steps} decisions of the run. */
        public double sigmaAt(long steps) {
            if (sigmaDecaySteps == 0 || steps >= sigmaDecaySteps) {
                return sigmaDecaySteps == 0 ? sigma : sigmaFinal;
            }
            return sigma + (sigmaFinal - sigma) * steps / (double) sigmaDecaySteps;
        }
    }

    /**
     * The training driver ({@link Trainer}).
     *
     * @param episodes episodes of a run (the app's budget; paper Fig. 6, 9, 10 show ~4000)
     * @param updatesPerStep gradient updates per decision stored (DDPG uses 1)
     * @param maxDecisionsPerEpisode a safety cut-off, treated as truncation, if the task never ends
     * @param movingAverageWindow episodes in the moving-average reward
     * @param parallelEpisodes 1: learn online, updating after every decision; K > 1: play K
     *     episodes at once with a frozen policy snapshot, then do their updates
     * @param checkpointEveryEpisodes save a checkpoint this often (0 = only at the end)
     * @param criticWarmupDecisions decisions after the random warm-up during which only the critic
     *     learns (optional, 0 when absent): a pretrained actor keeps its actions until the critic
     *     has fitted their values, instead of following the gradient of an untrained critic
     */
    public record Training(int episodes, int updatesPerStep, int maxDecisionsPerEpisode, int movingAverageWindow,
            int parallelEpisodes, int checkpointEveryEpisodes, int criticWarmupDecisions) {

        static Training parse(Json j) {
            j.allow("comment");
            Training t = new Training(j.integer("episodes", 0, Integer.MAX_VALUE), j.integer("updatesPerStep", 0, 1000),
                    j.integer("maxDecisionsPerEpisode", 1, Integer.MAX_VALUE),
                    j.integer("movingAverageWindow", 1, 1_000_000), j.integer("parallelEpisodes", 1, 4096),
                    j.integer("checkpointEveryEpisodes", 0, Integer.MAX_VALUE),
                    j.has("criticWarmupDecisions") ? j.integer("criticWarmupDecisions", 0, Integer.MAX_VALUE) : 0);
            j.requireNoUnknownFields();
            return t;
        }
    }

    /**
     * Actor pretraining by regression on (observation, action) examples (paper sec. 4.4).
     *
     * @param epochs passes over the training part of the examples
     * @param batchSize examples per gradient step
     * @param learningRate Adam learning rate while pretraining (the DDPG actorLr is restored after)
     * @param validationFraction share of the examples held out to measure generalisation
     * @param policyObservations when the actor starts from a trained policy instead (train
     *     --init-actor POLICY.json), how many observations its normaliser's statistics count as;
     *     0 (also when absent) means not set, and such a start refuses
     */
    public record Pretrain(int epochs, int batchSize, double learningRate, double validationFraction,
            long policyObservations) {

        static Pretrain parse(Json j) {
            j.allow("comment");
            Pretrain p = new Pretrain(j.integer("epochs", 1, 1_000_000), j.integer("batchSize", 1, 1 << 16),
                    j.positive("learningRate"), j.number("validationFraction", 0, 0.9),
                    j.has("policyObservations") ? j.integer("policyObservations", 0, Integer.MAX_VALUE) : 0);
            j.requireNoUnknownFields();
            return p;
        }
    }

    /**
     * CMA-ES for the imitation examples (paper sec. 4.4, Hansen 2006).
     *
     * @param population offspring per generation (0 = the default 4 + 3 ln n)
     * @param initialSigma initial step size as a fraction of each parameter's range
     * @param maxEvaluations objective evaluations per problem
     * @param workers independent problems solved at once
     */
    public record Cmaes(int population, double initialSigma, int maxEvaluations, int workers) {

        static Cmaes parse(Json j) {
            j.allow("comment");
            Cmaes c = new Cmaes(j.integer("population", 0, 100_000), j.number("initialSigma", 1e-9, 1),
                    j.integer("maxEvaluations", 1, Integer.MAX_VALUE), j.integer("workers", 1, 1024));
            j.requireNoUnknownFields();
            return c;
        }
    }

    private static boolean requiredBool(Json j, String name) {
        if (!j.has(name)) {
            throw j.fieldError(name, "required field is missing");
        }
        return j.bool(name, false);
    }

    private static List<Integer> widths(Json j, String name) {
        double[] w = j.numbers(name, -1);
        if (w.length < 1 || w.length > 8) {
            throw j.fieldError(name, "needs 1 to 8 hidden layer widths, got " + w.length);
        }
        List<Integer> out = new ArrayList<>();
        for (double x : w) {
            if (x != Math.rint(x) || x < 1 || x > 4096) {
                throw j.fieldError(name, "widths must be integers in [1, 4096], got " + x);
            }
            out.add((int) x);
        }
        return out;
    }
}
