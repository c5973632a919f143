package handsim.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.ControllerConfig;
import handsim.control.ThrowPolicy;
import handsim.sim.Simulator;
import handsim.sim.ode.IsolatedEngine;
import handsim.task.EpisodeLimits;
import handsim.task.FlipTask;
import handsim.task.LaunchDistribution;
import handsim.task.LoopRecord;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** An evaluation asks a policy's opening for each episode's first throw and nothing else. */
@Tag("slow")
class OpeningThrowTest {

    /** A seed whose nominal flip fails at its second throw (measured: 1 flip-and-catch loop in a row; as ThrowPlannerTest). */
    private static final long NOMINAL_FAILS = 103;

    /**
     * Seed 103 (NOMINAL_FAILS): the nominal flip, caught as the controller
     * catches (no arm rest), succeeds at the first throw and fails at the second. With the nominal throw as both
     * the opening and the loop's policy, the opening is asked once, at the first decision, the other
     * policy at every later one, and the episode is the one a single policy plays, bit for bit.
     */
    @Test
    void theOpeningIsAskedAtTheFirstThrowOnly() {
        ControllerConfig controller = ControllerConfig.load(Home.resolve("configs/controller.json"));
        FlipTask task = TestSupport.configs().flip().newTask("can").catchingAs(controller.catchStyle()).withoutArmRest();
        List<Double> openingAsked = new ArrayList<>(), restAsked = new ArrayList<>();
        ThrowPolicy withOpening = ThrowPolicy.withOpening(obs -> {
            openingAsked.add(obs.time());
            return task.nominalThrow();
        }, obs -> {
            restAsked.add(obs.time());
            return task.nominalThrow();
        });
        List<LoopRecord> opened = run(controller, task, withOpening);
        List<LoopRecord> single = run(controller, task, obs -> task.nominalThrow());

        assertEquals(3, opened.size(), "the throw-in's catch and two throws: " + opened);
        assertEquals(1, openingAsked.size(), "the opening chose one throw");
        // the second throw, and a third: decided in the tick the failed second throw's catch is judged, before the episode stops
        assertEquals(2, restAsked.size(), "the loop's policy chose the others");
        assertTrue(openingAsked.get(0) < restAsked.get(0), "the opening's came first: " + openingAsked + " " + restAsked);
        assertEquals(single.toString(), opened.toString(), "the same throws give the same episode");
    }

    private static List<LoopRecord> run(ControllerConfig controller, FlipTask task, ThrowPolicy policy) {
        CatchEvaluation evaluation = new CatchEvaluation(controller, EpisodeLimits.parse(Json.load(Home.resolve("configs/episode.json"))),
                LaunchDistribution.load(Home.resolve("configs/launch.json")), TestSupport.object("can"), task, policy);
        try (Simulator sim = IsolatedEngine.simulator(TestSupport.model(), TestSupport.simConfig())) {
            return evaluation.runWhileSuccessful(sim, NOMINAL_FAILS, 5);
        }
    }
}
