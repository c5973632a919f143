package handsim.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.ControllerConfig;
import handsim.control.ThrowDecision;
import handsim.planning.PlannerConfig;
import handsim.sim.Simulator;
import handsim.sim.ode.IsolatedEngine;
import handsim.task.CatchThrowEpisode;
import handsim.task.EpisodeLimits;
import handsim.task.HeightGoals;
import handsim.task.LaunchDistribution;
import handsim.task.ThrowTask;
import java.lang.reflect.Array;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * A checkpoint of every kind of episode (height, box, flip, planned flip) restored into a twin
 * episode on another engine continues bit for bit: after every tick the twin's world state and
 * every field of its {@link handsim.task.EpisodeState} (read by reflection, so a field that
 * {@code copy()} missed shows) equal the live episode's exactly. Exact equality is the
 * expectation: the twin replays the same floating-point operations in the same order.
 */
@Tag("slow")
class EpisodeCheckpointTest {

    /**
     * Ticks compared after the checkpoint: 1.6 s of simulated time (2 ms a tick), past the end of
     * the loop under way (a loop lasts about 1.3 s: THROW, flight, CATCH, MIDDLE) and into the next.
     */
    static final int TICKS = 800;

    private final ControllerConfig controller = ControllerConfig.load(Home.resolve("configs/controller.json"));

    private CatchEvaluation evaluation(ThrowTask task, String object) {
        return CatchEvaluation.nominal(controller, EpisodeLimits.parse(Json.load(Home.resolve("configs/episode.json"))),
                LaunchDistribution.load(Home.resolve("configs/launch.json")), TestSupport.object(object), task);
    }

    private static Simulator engine() {
        return IsolatedEngine.simulator(TestSupport.model(), TestSupport.simConfig());
    }

    @Test
    void aHeightEpisodeContinuesBitForBit() {
        // a fixed goal: the twin shares the live episode's task, which a random goal would move on
        ThrowTask height = TestSupport.configs().height().newTask(HeightGoals.fixed(1.2));
        assertContinuesBitForBit(evaluation(height, "sphere"), 3, null);
    }

    @Test
    void aBoxEpisodeContinuesBitForBit() {
        assertContinuesBitForBit(evaluation(TestSupport.configs().task("box").newTask("sphere"), "sphere"), 4, null);
    }

    @Test
    void aFlipEpisodeContinuesBitForBit() {
        assertContinuesBitForBit(evaluation(TestSupport.configs().flip().newTask("can"), "can"), 5, null);
    }

    @Test
    void aPlannedFlipEpisodeContinuesBitForBit() {
        PlannerConfig oneTry = new PlannerConfig(List.of(new PlannerConfig.Round(2, 0.05)), 0.9, 0);
        try (Simulator planning = engine()) {
            assertContinuesBitForBit(evaluation(TestSupport.configs().flip().newTask("can"), "can").planned(oneTry, planning), 5, planning);
        }
    }

    /**
     * Runs the episode of {@code seed} to its first throw's decision and 100 ticks into that
     * throw (the planner choosing it when there is one), checkpoints it, plays on {@link #TICKS}
     * ticks, then restores the checkpoint into a twin episode on another engine and plays the same
     * ticks there, comparing both after every tick.
     */
    private void assertContinuesBitForBit(CatchEvaluation evaluation, long seed, Simulator planning) {
        try (Simulator live = engine(); Simulator other = engine()) {
            CatchThrowEpisode episode = evaluation.start(live, seed);
            while (episode.loops().isEmpty()) {
                evaluation.tick(episode, seed);
            }
            for (int i = 0; i < 100; i++) {
                evaluation.tick(episode, seed);
            }
            assertEquals(CatchThrowEpisode.Status.RUNNING, episode.status(), "the throw-in was caught");
            CatchThrowEpisode.Checkpoint checkpoint = episode.checkpoint();
            List<String> played = play(episode);

            CatchThrowEpisode twin = episode.twinOn(other);
            twin.restore(checkpoint);
            List<String> replayed = play(twin);
            for (int t = 0; t < TICKS; t++) {
                assertEquals(played.get(t), replayed.get(t), "tick " + t + " after the checkpoint");
            }
            assertTrue(episode.loops().size() > checkpoint.loopCount(), "a loop ended in the ticks compared");
            assertNotEquals(played.get(0), played.get(TICKS - 1), "the world moved");
        }
    }

    /** {@link #TICKS} ticks, each throw the task's nominal one; the episode's whole state after each. */
    private static List<String> play(CatchThrowEpisode e) {
        List<String> states = new ArrayList<>();
        for (int t = 0; t < TICKS && e.status() == CatchThrowEpisode.Status.RUNNING; t++) {
            if (e.decision() != null) {
                e.decide(ThrowDecision.of(e.task().nominalThrow()));
            } else {
                e.tick();
            }
            StringBuilder sb = new StringBuilder();
            describe("world", e.sim().captureState(), sb, new IdentityHashMap<>());
            describe("episode", e.state(), sb, new IdentityHashMap<>());
            states.add(sb.toString());
        }
        while (states.size() < TICKS) {
            states.add("ended");
        }
        return states;
    }

    /**
     * Every field of {@code v}, recursively through handsim's own classes, arrays, lists and
     * optionals, with doubles as their exact bits: a line per value.
     */
    private static void describe(String path, Object v, StringBuilder out, Map<Object, Boolean> seen) {
        if (v == null || v instanceof Number || v instanceof Boolean || v instanceof String || v instanceof Enum<?>) {
            out.append(path).append('=').append(v instanceof Double d ? Long.toHexString(Double.doubleToRawLongBits(d)) : v)
                    .append('\n');
            return;
        }
        if (seen.put(v, true) != null) {
            out.append(path).append("=<cycle>\n");
            return;
        }
        if (v.getClass().isArray()) {
            for (int i = 0; i < Array.getLength(v); i++) {
                describe(path + "[" + i + "]", Array.get(v, i), out, seen);
            }
        } else if (v instanceof List<?> list) {
            for (int i = 0; i < list.size(); i++) {
                describe(path + "[" + i + "]", list.get(i), out, seen);
            }
        } else if (v instanceof Optional<?> o) {
            describe(path + "?", o.orElse(null), out, seen);
        } else if (v.getClass().getName().startsWith("handsim.")) {
            for (Class<?> c = v.getClass(); c != null && c != Object.class && c != Record.class; c = c.getSuperclass()) {
                for (Field f : c.getDeclaredFields()) {
                    if (Modifier.isStatic(f.getModifiers())) {
                        continue;
                    }
                    f.setAccessible(true);
                    try {
                        describe(path + "." + f.getName(), f.get(v), out, seen);
                    } catch (IllegalAccessException e) {
                        throw new AssertionError(e);
                    }
                }
            }
        } else {
            out.append(path).append('=').append(v).append('\n');
        }
        seen.remove(v); // only a cycle is cut short: a value shared by two fields is written twice
    }
}
