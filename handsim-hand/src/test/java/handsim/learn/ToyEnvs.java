package handsim.learn;

/** Small tasks without physics on which the learner must reach a known optimum. */
final class ToyEnvs {

    private ToyEnvs() {
    }

    /**
     * Like the real throw task: each decision sees a random goal g in [-1, 1]^2 (plus two
     * distractor dimensions) and is rewarded exp(-10 |a - f(g)|) (the shape of paper eq. 5)
     * for an action a in [-1, 1]^3; goals are independent of actions. Episodes are
     * {@code length} decisions, then truncated. The best reward is 1 per decision, at a = f(g).
     */
    static final class GoalReaching implements Env {

        private final int length;
        private Rng rng;
        private double[] obs;
        private int t;

        GoalReaching(int length) {
            this.length = length;
        }

        /** The known smooth map from goal to best action, inside [-0.8, 0.8]^3. */
        static double[] best(double g1, double g2) {
            return new double[] {0.5 * g1 + 0.3 * g2, 0.6 * Math.sin(1.5 * g2), 0.5 * g1 * g2 - 0.2};
        }

        @Override
        public int observationSize() {
            return 4;
        }

        @Override
        public int actionSize() {
            return 3;
        }

        @Override
        public double[] reset(long seed) {
            rng = new Rng(seed);
            t = 0;
            obs = draw();
            return obs.clone();
        }

        private double[] draw() {
            return new double[] {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        }

        static double reward(double[] obs, double[] a) {
            double[] f = best(obs[0], obs[1]);
            double d2 = 0;
            for (int i = 0; i < 3; i++) {
                d2 += (a[i] - f[i]) * (a[i] - f[i]);
            }
            return Math.exp(-10 * Math.sqrt(d2));
        }

        @Override
        public Step step(double[] action) {
            double r = reward(obs, action);
            t++;
            obs = draw();
            return new Step(obs.clone(), r, false, t >= length);
        }
    }

    /**
     * Where terminal and truncated differ. The observation is a random context c in [-1, 1];
     * the action a in [-1, 1]. If a > 0.3 the decision pays 1 and the episode ends for real
     * (terminal); otherwise it pays 0.5 - 0.5 |a| and goes on. Episodes are cut off after
     * {@code length} decisions (truncated), although the task itself could go on forever.
     *
     * <p>With discount gamma, staying at a = 0 is worth 0.5 / (1 - gamma) (5 at gamma 0.9),
     * ending is worth 1: a learner that bootstraps across cut-offs avoids the end and its
     * "Episode Q0" tends to 0.5 / (1 - gamma). One that treated cut-offs as ends would value
     * staying at only 0.5 (1 - gamma^m) / (1 - gamma) with m decisions left before the cut-off.
     */
    static final class Cliff implements Env {

        static final double EDGE = 0.3;
        private final int length;
        private Rng rng;
        private int t;

        Cliff(int length) {
            this.length = length;
        }

        @Override
        public int observationSize() {
            return 1;
        }

        @Override
        public int actionSize() {
            return 1;
        }

        @Override
        public double[] reset(long seed) {
            rng = new Rng(seed);
            t = 0;
            return new double[] {rng.uniform(-1, 1)};
        }

        @Override
        public Step step(double[] action) {
            t++;
            double[] next = {rng.uniform(-1, 1)};
            if (action[0] > EDGE) {
                return new Step(next, 1.0, true, false);
            }
            return new Step(next, 0.5 - 0.5 * Math.abs(action[0]), false, t >= length);
        }
    }
}
