package handsim.task;

import handsim.config.Json;
import handsim.control.NominalThrows;
import handsim.control.ThrowParameters;
import handsim.control.ThrowSpace;
import handsim.math.Vec3;
import handsim.sim.Simulator;

/**
 * Throw to a desired height (paper sec. 4.2): every throw aims at a new apex height. Reward eq.
 * (5), with the sign slip of the printed exponent corrected (SPEC.md): a caught throw scores
 * {@code exp(-sharpness |apex - target|)}, a dropped one {@code -missWeight |p_p - p_d|} with
 * p_p where the object came down and p_d the neutral palm centre dropped to the ground.
 */
public final class HeightTask implements ThrowTask {

    /**
     * {@code configs/tasks/height.json}.
     *
     * @param low, high range of the target apex heights (m, world)
     * @param sharpness the 10 of eq. (5) (1/m)
     * @param missWeight the 0.1 of eq. (5)'s miss term (1/m)
     * @param successTolerance a caught throw within this of its target counts as a success (m)
     * @param space the box of throw parameters for this task
     * @param lowestGoal the lowest apex a goal may have (m, excluded): the catch meets a falling
     *     object where it crosses the interception plane, 0.72 m high (configs/controller.json), so
     *     an apex must lie above it
     * @param highestGoal the highest (m, excluded): an apex of 3 m asks for a release at about
     *     sqrt(2 g (3 - 0.9)) = 6.4 m/s from a palm 0.9 m high, far past the throws the arm makes
     *     (its nominal throws reach 1.6 m)
     * @param evaluationThrows throws an evaluation episode attempts after the first catch by default
     */
    public record Config(double low, double high, double sharpness, double missWeight, double successTolerance,
            ThrowSpace space, double lowestGoal, double highestGoal, int evaluationThrows) {

        public static Config parse(Json j) {
            j.allow("comment", "goalLimitsComment", "evaluationThrowsComment");
            double[] limits = j.range("goalLimits");
            if (!(limits[0] > 0)) {
                throw j.fieldError("goalLimits", "heights must lie above 0 m, got [" + limits[0] + ", " + limits[1] + "]");
            }
            double[] range = j.range("goalRange");
            if (!(range[0] > limits[0] && range[1] < limits[1])) {
                throw j.fieldError("goalRange", "heights must lie in (" + limits[0] + ", " + limits[1]
                        + ") m, got [" + range[0] + ", " + range[1] + "]");
            }
            Config c = new Config(range[0], range[1], j.positive("sharpness"), j.number("missWeight", 0, 100),
                    j.positive("successTolerance"), ThrowSpace.parse(j.get("throwSpace")), limits[0], limits[1],
                    j.integer("evaluationThrows", 0, 100000));
            j.requireNoUnknownFields();
            return c;
        }

        /** Whether {@code height} may be a goal: inside the open interval of the goal limits. */
        public boolean allowsGoal(double height) {
            return height > lowestGoal && height < highestGoal;
        }

        /** The goal limits as a message gives them: "(0.7, 3.0) m". */
        public String goalLimits() {
            return "(" + lowestGoal + ", " + highestGoal + ") m";
        }
    }

    private final Config config;
    private final HeightGoals goals;
    private final NominalThrows nominal;
    private final Vec3 missTarget;

    /**
     * @param goals the target heights (shared with whoever steers them, e.g. the viewer)
     * @param neutralPalm the palm centre in the neutral pose (m, world): p_d lies below it
     */
    public HeightTask(Config config, HeightGoals goals, NominalThrows nominal, Vec3 neutralPalm, double groundHeight) {
        this.config = config;
        this.goals = java.util.Objects.requireNonNull(goals, "goals");
        this.nominal = nominal;
        this.missTarget = new Vec3(neutralPalm.x(), groundHeight, neutralPalm.z());
    }

    /** The task over the config's goal range. */
    public HeightTask(Config config, NominalThrows nominal, Vec3 neutralPalm, double groundHeight) {
        this(config, new HeightGoals(config.low(), config.high()), nominal, neutralPalm, groundHeight);
    }

    public HeightGoals goals() {
        return goals;
    }

    public Config config() {
        return config;
    }

    @Override
    public String name() {
        return "height";
    }

    @Override
    public int goalSize() {
        return 1;
    }

    @Override
    public void start(Simulator sim, long seed) {
        goals.reset(seed);
    }

    @Override
    public double[] goal() {
        return new double[] {goals.current()};
    }

    @Override
    public double targetHeight() {
        return goals.current();
    }

    @Override
    public void advance() {
        goals.advance();
    }

    @Override
    public ThrowParameters nominalThrow() {
        return nominal.forHeight(goals.current());
    }

    @Override
    public ThrowSpace throwSpace(ThrowSpace fallback) {
        return config.space();
    }

    /** eq. (5), corrected. */
    @Override
    public double reward(LoopRecord loop) {
        if (loop.caught()) {
            return Math.exp(-config.sharpness() * Math.abs(loop.apexHeight() - loop.targetHeight()));
        }
        return -config.missWeight() * loop.landing().distance(missTarget);
    }

    @Override
    public boolean success(LoopRecord loop) {
        return loop.caught() && Math.abs(loop.apexHeight() - loop.targetHeight()) <= config.successTolerance();
    }


}
