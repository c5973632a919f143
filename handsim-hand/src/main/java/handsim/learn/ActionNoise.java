package handsim.learn;

import handsim.learn.LearnerConfig.NoiseType;

/**
 * Exploration for one episode: uniform random actions during warm-up, otherwise Gaussian or
 * Ornstein-Uhlenbeck noise (DDPG paper, sec. 3) added to the actor's action and clipped to
 * [-1, 1]. One instance per episode, seeded by the episode's noise seed, so that an episode
 * played on any worker thread explores the same way.
 */
public final class ActionNoise {

    private final NoiseType type;
    private final double theta;
    private final Rng rng;
    private final double[] ou;

    public ActionNoise(NoiseType type, double ouTheta, int actionSize, long seed) {
        this.type = type;
        this.theta = ouTheta;
        this.rng = new Rng(seed);
        this.ou = new double[actionSize];
    }

    /** A uniform random action in [-1, 1]^k (warm-up). */
    public double[] randomAction() {
        double[] a = new double[ou.length];
        for (int i = 0; i < a.length; i++) {
            a[i] = rng.uniform(-1, 1);
        }
        return a;
    }

    /** {@code action} plus noise of scale {@code sigma}, clipped to [-1, 1]. */
    public double[] perturb(double[] action, double sigma) {
        double[] a = new double[action.length];
        for (int i = 0; i < a.length; i++) {
            double n = sigma * rng.nextGaussian();
            if (type == NoiseType.OU) {
                ou[i] += -theta * ou[i] + n; // x_{t+1} = x_t - theta x_t + sigma N(0, 1), dt = one decision
                n = ou[i];
            }
            a[i] = Normalizer.clip(action[i] + n, 1);
        }
        return a;
    }
}
