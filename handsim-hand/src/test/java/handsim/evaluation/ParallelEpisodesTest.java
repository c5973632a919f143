package handsim.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.ControllerConfig;
import handsim.model.HandModel;
import handsim.rollout.LocalRollouts;
import handsim.rollout.Rollouts;
import handsim.sim.SimConfig;
import handsim.sim.Simulator;
import handsim.sim.ode.IsolatedEngine;
import handsim.task.EpisodeLimits;
import handsim.task.EpisodeResult;
import handsim.task.HeightGoals;
import handsim.task.LaunchDistribution;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** Episodes on parallel workers, each with its own engine: same results whatever the number of workers. */
@Tag("slow")
class ParallelEpisodesTest {

    private final HandModel model = TestSupport.model();
    private final SimConfig config = TestSupport.simConfig();

    /** First catches of three seeded sphere episodes (about 1 s simulated each): one worker of two runs two. */
    private List<EpisodeResult> evaluate(int workers, List<Integer> order) {
        try (Rollouts<Simulator> rollouts = new LocalRollouts<>(workers, () -> IsolatedEngine.simulator(model, config))) {
            return rollouts.run(3, sim -> {
                // per worker: the evaluation holds a goal sequence, so each worker has its own
                CatchEvaluation evaluation = CatchEvaluation.nominal(
                        ControllerConfig.load(Home.resolve("configs/controller.json")),
                        EpisodeLimits.parse(Json.load(Home.resolve("configs/episode.json"))),
                        LaunchDistribution.load(Home.resolve("configs/launch.json")), TestSupport.object("sphere"),
                        TestSupport.heightTask(HeightGoals.fixed(1.2)));
                return i -> evaluation.run(sim, 1000 + i, 0, null);
            }, (i, r) -> order.add(i));
        }
    }

    @Test
    void episodeResultsAreBitIdenticalWithOneAndTwoWorkers() {
        List<Integer> order1 = new ArrayList<>(), order2 = new ArrayList<>();
        List<EpisodeResult> one = evaluate(1, order1);
        List<EpisodeResult> two = evaluate(2, order2);
        // records compare every double exactly (apex, penetration, torque ratio, duration, ...)
        assertEquals(one, two);
        assertEquals(List.of(0, 1, 2), order1, "results reach the listener in index order");
        assertEquals(List.of(0, 1, 2), order2, "results reach the listener in index order");
        for (int i = 0; i < 3; i++) {
            assertEquals(1000 + i, one.get(i).seed());
            assertTrue(one.get(i).firstCatch(), "the sphere of seed " + (1000 + i) + " is caught");
        }
    }
}
