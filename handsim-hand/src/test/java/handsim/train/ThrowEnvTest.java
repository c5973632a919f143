package handsim.train;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.ControllerConfig;
import handsim.control.ThrowParameters;
import handsim.control.ThrowSpace;
import handsim.learn.Env;
import handsim.sim.Simulator;
import handsim.sim.ode.OdeSimulator;
import handsim.task.HeightTask;
import handsim.task.StateVector;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The height task as an environment: one decision per THROW, terminal on a drop, reproducible from its seed. */
@Tag("slow")
class ThrowEnvTest {

    private final ControllerConfig cc = ControllerConfig.load(Home.resolve("configs/controller.json"));

    private static ThrowEnvFactory envs(ThrowSpace space) {
        return TestSupport.heightEnvs(space);
    }

    @Test
    void aResetIsAFunctionOfItsSeedAndTheStateEndsWithTheGoal() {
        try (Simulator a = new OdeSimulator(TestSupport.model(), TestSupport.simConfig());
                Simulator b = new OdeSimulator(TestSupport.model(), TestSupport.simConfig())) {
            ThrowEnv first = envs(cc.throwSpace()).create(a), second = envs(cc.throwSpace()).create(b);
            double[] s1 = first.reset(11);
            second.reset(12); // another episode on the other simulator first: no state carries over
            double[] s2 = second.reset(11);
            assertArrayEquals(s1, s2, 0, "same seed, same first state, bit for bit");
            assertEquals(StateVector.Encoding.PAPER.baseSize() + 1, first.observationSize());
            HeightTask.Config height = HeightTask.Config.parse(Json.load(Home.resolve("configs/tasks/height.json")));
            double goal = s1[StateVector.Encoding.PAPER.baseSize()];
            assertTrue(goal >= height.low() && goal <= height.high(), "goal from the task's range: " + goal);
            // the object rests in the hand when the throw is decided: within the hold distance of the palm centre
            double[] inPalm = {s1[6], s1[7], s1[8]};
            assertTrue(Math.sqrt(inPalm[0] * inPalm[0] + inPalm[1] * inPalm[1] + inPalm[2] * inPalm[2]) < 0.08);
        }
    }

    @Test
    void theNominalThrowIsCaughtAndRewardedByEquation5() {
        try (Simulator sim = new OdeSimulator(TestSupport.model(), TestSupport.simConfig())) {
            ThrowEnv env = envs(cc.throwSpace()).create(sim);
            double[] s = env.reset(3);
            double goal = s[StateVector.Encoding.PAPER.baseSize()];
            Env.Step step = env.step(cc.throwSpace().toAction(cc.nominalThrows().forHeight(goal)));
            assertFalse(step.terminal(), "the hand-tuned throw is caught");
            // eq. (5) for a catch: exp(-10 |apex - goal|), in (0, 1]; the nominal lands within 5 cm (docs/results.md)
            assertTrue(step.reward() > Math.exp(-10 * 0.05) && step.reward() <= 1, "reward " + step.reward());
        }
    }

    @Test
    void aCaughtThrowThatMissesItsGoalEndsTheEpisodeOnlyWhenTheRunSaysSo() {
        for (boolean endAtFailedThrow : new boolean[] {false, true}) {
            try (Simulator sim = new OdeSimulator(TestSupport.model(), TestSupport.simConfig())) {
                ThrowEnv env = TestSupport.heightEnvs(cc.throwSpace(), endAtFailedThrow).create(sim);
                double[] s = env.reset(3);
                double goal = s[StateVector.Encoding.PAPER.baseSize()];
                // the nominal throw for a height 0.3 m off the goal: caught (as every nominal throw of the
                // test above), its apex well outside the height task's success tolerance (configs/tasks/height.json)
                double aim = goal > 1.3 ? goal - 0.3 : goal + 0.3;
                Env.Step step = env.step(cc.throwSpace().toAction(cc.nominalThrows().forHeight(aim)));
                assertTrue(step.reward() > 0 && step.reward() < Math.exp(-10 * 0.2), "caught, far from the goal: " + step.reward());
                assertEquals(endAtFailedThrow, step.terminal(), "endAtFailedThrow " + endAtFailedThrow);
            }
        }
    }

    @Test
    void aThrowBeyondReachEndsTheEpisodeWithTheMissPenalty() {
        // a box whose largest sideways offset (0.5 m, about 4 m/s) throws the ball far beyond the arm's reach
        ThrowSpace wide = new ThrowSpace(new double[] {-0.5, 0.08, -0.5, -0.1, -0.1, -0.1, 0}, new double[] {0.5, 0.4, 0.5, 0.1, 0.1, 0.1, 0.2});
        try (Simulator sim = new OdeSimulator(TestSupport.model(), TestSupport.simConfig())) {
            ThrowEnv env = envs(wide).create(sim);
            env.reset(3);
            double[] action = wide.toAction(new ThrowParameters(new handsim.math.Vec3(0, 0.2, 0.5), handsim.math.Vec3.ZERO, 0.08));
            Env.Step step = env.step(action);
            assertTrue(step.terminal(), "a drop is a real end");
            assertFalse(step.truncated());
            // eq. (5) for a miss: -0.1 |landing - p_d|, the landing a good way from below the palm
            assertTrue(step.reward() < -0.1 * 0.3 && step.reward() > -0.1 * 5, "reward " + step.reward());
        }
    }
}
