package handsim.train;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.Home;
import handsim.control.ControllerConfig;
import handsim.control.Observation;
import handsim.control.ThrowParameters;
import handsim.control.ThrowPolicy;
import handsim.learn.Env;
import handsim.sim.Simulator;
import handsim.sim.ode.OdeSimulator;
import handsim.task.ThrowTask;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * A gated environment (DAgger for one rest of the object): the lead-in policy throws every
 * decision the gate keeps from the learner, the learner sees only the ones it lets through, and
 * an episode is cut off at the gate's throw number. On the height task with its nominal throw,
 * which loops (CatchLoopTest), so that the throw numbers are known in advance.
 */
@Tag("slow")
class TeachableThrowEnvTest {

    private final ControllerConfig cc = ControllerConfig.load(Home.resolve("configs/controller.json"));

    /** The nominal throw of {@code task}, recording the throw number it was asked for. */
    private static ThrowPolicy recording(ThrowTask task, List<Integer> asked) {
        return new ThrowPolicy() {
            @Override
            public ThrowParameters decide(Observation observation) {
                return task.nominalThrow();
            }

            @Override
            public ThrowParameters decide(Observation observation, int throwIndex) {
                asked.add(throwIndex);
                return task.nominalThrow();
            }
        };
    }

    @Test
    void theLeadInThrowsUntilTheGateLetsTheLearnerThrow() {
        try (Simulator sim = new OdeSimulator(TestSupport.model(), TestSupport.simConfig())) {
            ThrowEnv env = TestSupport.heightEnvs(cc.throwSpace()).create(sim);
            List<Integer> ledIn = new ArrayList<>();
            int[] gateAsked = {0};
            // the gate is asked from throw 2 on (throw 1 is made from the thrown-in object): it lets the 3rd and later asks through
            TeachableThrowEnv gated = new TeachableThrowEnv(env, null,
                    new TeachableThrowEnv.Gate(obs -> ++gateAsked[0] >= 3, recording(env.task(), ledIn), 100));
            assertNotNull(gated.reset(5), "the learner's first decision");
            assertEquals(List.of(1, 2, 3), ledIn, "throws 1-3 by the lead-in");
            assertEquals(4, env.episode().loops().size(), "the learner makes throw 4");
            Env.Step s = gated.step(cc.throwSpace().toAction(env.task().nominalThrow()));
            assertFalse(s.done());
            assertEquals(List.of(1, 2, 3), ledIn, "throw 5 is the learner's again: the gate lets it through");
            assertEquals(5, env.episode().loops().size());
        }
    }

    @Test
    void anEpisodeWithoutALearnersDecisionBeforeTheCutOffGivesNone() {
        try (Simulator sim = new OdeSimulator(TestSupport.model(), TestSupport.simConfig())) {
            ThrowEnv env = TestSupport.heightEnvs(cc.throwSpace()).create(sim);
            List<Integer> ledIn = new ArrayList<>();
            TeachableThrowEnv gated = new TeachableThrowEnv(env, null,
                    new TeachableThrowEnv.Gate(obs -> false, recording(env.task(), ledIn), 3));
            assertNull(gated.reset(5), "no decision is the learner's up to throw 3, the cut-off");
            assertEquals(List.of(1, 2, 3), ledIn, "throws 1 to maxLoops made, as evaluate makes --loops throws");
            // a learner's throw whose episode is then cut off: truncated, not ended by the task
            List<Integer> ledIn2 = new ArrayList<>();
            int[] gateAsked = {0};
            TeachableThrowEnv once = new TeachableThrowEnv(env, null,
                    new TeachableThrowEnv.Gate(obs -> ++gateAsked[0] == 1, recording(env.task(), ledIn2), 4));
            assertNotNull(once.reset(5), "throw 2 is the learner's");
            Env.Step s = once.step(cc.throwSpace().toAction(env.task().nominalThrow()));
            assertEquals(List.of(1, 3, 4), ledIn2, "throws 3 and 4 by the lead-in, then the cut-off");
            assertTrue(s.truncated() && !s.terminal(), "cut off: " + s);
            assertEquals(env.task().reward(env.episode().loops().get(2)), s.reward(), 0, "the reward of the learner's throw, throw 2");
        }
    }
}
