package handsim.planning;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.ControllerConfig;
import handsim.control.Observation;
import handsim.control.ThrowDecision;
import handsim.control.ThrowSpace;
import handsim.evaluation.CatchEvaluation;
import handsim.sim.Simulator;
import handsim.sim.ode.IsolatedEngine;
import handsim.task.CatchThrowEpisode;
import handsim.task.EpisodeLimits;
import handsim.task.FlipTask;
import handsim.task.LaunchDistribution;
import handsim.task.LoopRecord;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The DAgger teacher on the can's flip: one decision labelled in a twin world. */
@Tag("slow")
class ThrowTeacherTest {

    private final ControllerConfig controller = ControllerConfig.load(Home.resolve("configs/controller.json"));
    private final Json shippedFile = Json.load(Home.resolve("configs/train/flip-dagger.json"));
    private final ThrowTeacher.Config shipped = ThrowTeacher.Config.parse(shippedFile.get("teacher"));

    private static Simulator engine() {
        return IsolatedEngine.simulator(TestSupport.model(), TestSupport.simConfig());
    }

    /**
     * Seed 103 (ThrowPlannerTest.NOMINAL_FAILS): the nominal flip, caught as the controller
     * catches, succeeds at the first throw and fails at the second. The teacher keeps the first as
     * its own label at the cost of one try; at the second it finds another throw, which the live
     * hand then makes with success (the twin is exact); labelling leaves the live episode where it
     * was.
     */
    @Test
    void aSuccessfulThrowIsItsOwnLabelAndAFailedOneGetsTheNearestThatWorks() {
        // caught as the controller catches, no arm rest, as in ThrowPlannerTest, where the seed was measured
        FlipTask task = TestSupport.configs().flip().newTask("can").catchingAs(controller.catchStyle()).withoutArmRest();
        ThrowSpace space = task.throwSpace(controller.throwSpace());
        double[] nominal = space.toAction(task.nominalThrow());
        CatchEvaluation evaluation = new CatchEvaluation(controller, EpisodeLimits.parse(Json.load(Home.resolve("configs/episode.json"))),
                LaunchDistribution.load(Home.resolve("configs/launch.json")), TestSupport.object("can"), task,
                CatchEvaluation.DECIDED_BY_CALLER);
        try (Simulator sim = engine(); Simulator twin = engine()) {
            ThrowTeacher teacher = new ThrowTeacher(shipped, task, space, twin);
            CatchThrowEpisode episode = evaluation.start(sim, ThrowPlannerTest.NOMINAL_FAILS);
            episode.advanceToDecision();
            ThrowTeacher.Label first = teacher.label(episode, nominal, 1);
            assertTrue(first.proposalSucceeded());
            assertArrayEquals(nominal, first.action(), 0);
            assertEquals(1, first.tries());
            assertEquals(1, first.robustness(), "no robustness check in the shipped teacher");
            episode.decide(ThrowDecision.of(space.fromAction(first.action())));

            Observation second = episode.advanceToDecision();
            ThrowTeacher.Label label = teacher.label(episode, nominal, 2);
            assertTrue(second.sameValues(episode.decision()), "the live episode waits where it did");
            assertFalse(label.proposalSucceeded(), "the nominal flip fails here");
            assertNotNull(label.action(), "the teacher found a throw that works");
            assertTrue(label.tries() > 1 && label.tries() <= shipped.maxTries(), label.tries() + " tries");
            assertFalse(label.trials().get(0).success());
            assertTrue(label.trials().get(label.tries() - 1).success(), "the search stops at its first success");
            episode.decide(ThrowDecision.of(space.fromAction(label.action())));
            assertNotNull(episode.advanceToDecision(), "the label played live keeps the episode going");
            LoopRecord made = episode.loops().get(2);
            assertTrue(task.success(made), "the label played live flips and is caught as in the twin: " + made);
        }
    }

    @Test
    void centringWithoutARobustnessCheckIsRefusedByName() {
        Json bad = Json.of("test", Json.withOverrides("test", shippedFile.node(), Map.of("teacher.centre", "true",
                "teacher.robustnessTries", "0")));
        ConfigException e = assertThrows(ConfigException.class, () -> ThrowTeacher.Config.parse(bad.get("teacher")));
        assertTrue(e.getMessage().contains("centre"), e.getMessage());
    }
}
