package handsim.sim.ode;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.model.HandModel;
import handsim.rollout.LocalRollouts;
import handsim.rollout.Rollouts;
import handsim.sim.SimConfig;
import handsim.sim.Simulator;
import handsim.sim.WorldState;
import handsim.task.HeldBallScenario;
import handsim.task.ServoLoop;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Worlds stepped by handsim's step on parallel threads of one JVM, sharing one copy of ode4j
 * (no {@link IsolatedEngine} class loader): bit-identical to the same worlds stepped one after
 * another. The step draws its row order from its own generator, and the rest of ode4j that a
 * step uses (its colliders, its bodies and geoms) keeps no state between worlds.
 */
@Tag("slow")
class HandsimWorkersTest {

    private final HandModel m = TestSupport.model();
    private final SimConfig config = TestSupport.simConfig().withStepper(SimConfig.Stepper.HANDSIM);

    /** The held ball of seeds 1-6 after 0.8 s (its catch and 0.2 s held): every body's state and the generator's. */
    private List<double[]> run(int workers) {
        try (Rollouts<Simulator> rollouts = new LocalRollouts<>(workers, () -> new OdeSimulator(m, config))) {
            return rollouts.run(6, sim -> i -> {
                HeldBallScenario scenario = new HeldBallScenario(new ServoLoop(sim, TestSupport.pd(m)), TestSupport.object("sphere"), 0.2,
                        1 + i);
                for (int k = 0; k < 4000; k++) {
                    scenario.step();
                }
                assertTrue(sim.handContacts().any(), "seed " + (1 + i) + ": the ball is held");
                WorldState s = sim.captureState();
                double[] out = Arrays.copyOf(s.bodies(), s.bodies().length + 4);
                out[s.bodies().length] = s.object().get().position().x();
                out[s.bodies().length + 1] = s.object().get().position().y();
                out[s.bodies().length + 2] = s.object().get().position().z();
                out[s.bodies().length + 3] = s.randomSeed();
                return out;
            });
        }
    }

    @Test
    void oneAndTwoWorkersOnOneOde4jGiveBitIdenticalWorlds() {
        List<double[]> one = run(1), two = run(2);
        List<String> differing = new ArrayList<>();
        for (int i = 0; i < one.size(); i++) {
            if (!Arrays.equals(one.get(i), two.get(i))) {
                differing.add("seed " + (1 + i));
            }
        }
        assertEquals(List.of(), differing, "worlds that differ between one worker and two");
        // the seeds lead to different worlds: the comparison is not of six copies of one run
        assertTrue(!Arrays.equals(one.get(0), one.get(1)));
    }
}
