package handsim.train;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.ControllerConfig;
import handsim.evaluation.CatchEvaluation;
import handsim.evaluation.HeightErrors;
import handsim.sim.SimConfig;
import handsim.sim.Simulator;
import handsim.sim.ode.OdeSimulator;
import handsim.task.EpisodeLimits;
import handsim.task.EpisodeResult;
import handsim.task.LaunchDistribution;
import handsim.task.LoopRecord;
import handsim.task.ThrowTask;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Regression of the trained policies in models/policies: each still does its task in the
 * current simulator and controller. A change to the physics, the controller or the task that
 * the policy was trained on shows up here before it shows up in a long evaluation.
 */
@Tag("slow")
class ShippedPoliciesTest {

    /**
     * The shipped height policy, 20 throws to seeded random goals in 1.0-1.4 m (seed 7, the
     * test seed of the 320-loop evaluation in docs/results.md, which dropped nothing): every
     * throw is caught, and the mean |apex - goal| stays within 3 cm (the evaluation measured 1.42 cm; the
     * nominal throw's table gives ~1.5 cm, so 3 cm catches a policy that does not aim).
     */
    @Test
    void theHeightPolicyCatchesTwentyThrowsInARowNearTheirGoals() {
        CatchEvaluation evaluation = evaluation("height", "sphere");
        EpisodeResult r;
        try (Simulator sim = new OdeSimulator(TestSupport.model(), TestSupport.simConfig())) {
            r = evaluation.run(sim, 7, 20, null);
        }
        assertTrue(r.firstCatch(), "the throw-in is caught");
        assertEquals(20, r.loopsCompleted(), "20 throws caught in a row: " + r);
        double err = HeightErrors.of(r.loops()).absMean();
        assertTrue(err < 0.03, "mean |apex - goal| " + err + " m");
    }

    /**
     * The shipped can-flip controller's golden run (models/policies/flip-can.json, its opening
     * flip-can-opening.json making the first throw): from the throw-in of seed 30001 (fixed before
     * any result on it was seen, docs/results.md) it makes the 10 flip-and-catch loops in a row the
     * learned-flipping goal asks for, with the task's catch (configs/tasks/flip.json: level and
     * turned, 7.5 mm toward the thumb) and arm rest; its first throw turns the can 449.218425
     * degrees end over end, its second 168.482536, its tenth 244.508052, all as measured with these
     * policies, physics and controller, with ode4j's quickStep, the step the policies were trained
     * with (the default step, handsim's, gives the same figures within their standard errors over
     * many episodes, docs/results.md, but other bits: on this one seed it drops the can at the 9th
     * throw). A guard that they still do what they did, not a measure of the policies (their means
     * are in docs/results.md); the turns, doubles from a deterministic simulation, are compared to
     * 1e-6 degrees.
     */
    @Test
    void theCanFlipPolicyRepeatsItsGoldenRunOnTheGuardSeed() {
        CatchEvaluation evaluation = evaluation("flip", "can");
        List<LoopRecord> loops;
        try (Simulator sim = new OdeSimulator(TestSupport.model(), TestSupport.simConfig().withStepper(SimConfig.Stepper.ODE4J))) {
            loops = evaluation.runWhileSuccessful(sim, 30001, 10);
        }
        assertEquals(10, evaluation.successesInARow(loops), "flip-and-catch loops in a row: " + loops);
        assertEquals(449.218425, Math.toDegrees(loops.get(1).flightRotation()), 1e-6, "the first throw's turn (deg): " + loops);
        assertEquals(168.482536, Math.toDegrees(loops.get(2).flightRotation()), 1e-6, "the second throw's turn (deg): " + loops);
        assertEquals(244.508052, Math.toDegrees(loops.get(10).flightRotation()), 1e-6, "the tenth throw's turn (deg): " + loops);
    }

    /** An evaluation of {@code task} with {@code object} thrown by the shipped policy (and its opening, when one ships). */
    static CatchEvaluation evaluation(String task, String object) {
        ControllerConfig cc = ControllerConfig.load(Home.resolve("configs/controller.json"));
        ThrowTask t = TestSupport.configs().task(task).newTask(object);
        Path file = ThrowPolicyFile.shipped(task, object);
        return new CatchEvaluation(cc, EpisodeLimits.parse(Json.load(Home.resolve("configs/episode.json"))),
                LaunchDistribution.load(Home.resolve("configs/launch.json")), TestSupport.object(object), t,
                ThrowPolicyFile.throwPolicy(file, ThrowPolicyFile.shippedOpening(task, object), ThrowPolicyFile.shippedRest(task, object), t, TestSupport.object(object),
                        handsim.task.StateVector.Hand.of(TestSupport.model())));
    }
}
