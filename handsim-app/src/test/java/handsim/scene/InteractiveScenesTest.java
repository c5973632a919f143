package handsim.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.ControllerConfig;
import handsim.evaluation.CatchEvaluation;
import handsim.sim.ode.OdeSimulator;
import handsim.task.EpisodeLimits;
import handsim.task.Goal;
import handsim.task.HeightGoals;
import handsim.task.LaunchDistribution;
import handsim.taskdef.SteeredTask;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** What a watcher can ask of the scenes: switching task, object and controller; moving the goal. */
@Tag("fast")
class InteractiveScenesTest {

    /** A catalog whose only available setup is the height task with the nominal controller. */
    static final class OnlyHeightNominal implements SceneCatalog {
        final List<SceneSetup> opened = new ArrayList<>();
        final List<FakeScene> scenes = new ArrayList<>();

        @Override
        public List<String> tasks() {
            return List.of("height", "box", "flip");
        }

        @Override
        public List<String> objects() {
            return List.of("sphere", "can");
        }

        @Override
        public List<String> controllers() {
            return List.of("nominal", "learned");
        }

        @Override
        public Opened open(SceneSetup wanted) {
            List<String> notes = new ArrayList<>();
            SceneSetup shown = wanted;
            if (!wanted.task().equals("height")) {
                notes.add(wanted.task() + " not available");
                shown = shown.withTask("height");
            }
            if (!wanted.controller().equals("nominal")) {
                notes.add(wanted.controller() + " not available");
                shown = shown.withController("nominal");
            }
            opened.add(shown);
            scenes.add(new FakeScene());
            return new Opened(scenes.get(scenes.size() - 1), shown, notes);
        }
    }

    @Test
    void switchingFallsBackWithANoteAndAPersistentWarningButNeverFails() {
        OnlyHeightNominal catalog = new OnlyHeightNominal();
        SwitchingScene s = new SwitchingScene(catalog, new SceneSetup("height", "sphere", "learned", 1));
        assertEquals(List.of("learned not available"), s.openingNotes());
        assertEquals("nominal", s.shown().controller());
        assertEquals("learned not available", s.status().get(InteractiveScene.FALLBACK), "shown until resolved");

        String note = s.apply(SceneCommand.TOGGLE_CONTROLLER);
        assertEquals("nominal", s.shown().controller());
        assertFalse(s.status().containsKey(InteractiveScene.FALLBACK), "toggled to nominal: nothing substituted");
        assertTrue(note.contains("nominal"), note);

        note = s.apply(SceneCommand.NEXT_TASK);
        assertTrue(note.contains("box not available"), note);
        assertEquals("height", s.shown().task());
        s.apply(SceneCommand.NEXT_TASK);
        s.apply(SceneCommand.NEXT_TASK);
        assertEquals("height", s.status().get("task"));
        assertFalse(s.status().containsKey(InteractiveScene.FALLBACK), "cycled back to height");

        s.apply(SceneCommand.NEXT_OBJECT);
        assertEquals("can", s.status().get("object"));
        assertEquals(6, catalog.opened.size(), "the first scene and one per switch");
        for (int i = 0; i < 5; i++) {
            assertTrue(catalog.scenes.get(i).closed, "a scene switched away from is closed");
        }
        s.close();
        assertTrue(catalog.scenes.get(5).closed);
    }

    @Test
    void otherCommandsGoToTheSceneShown() {
        OnlyHeightNominal catalog = new OnlyHeightNominal();
        SwitchingScene s = new SwitchingScene(catalog, new SceneSetup("height", "sphere", "nominal", 1));
        assertEquals("did GOAL_UP", s.apply(SceneCommand.GOAL_UP));
    }

    @Test
    void heightGoalsMoveInStepsWithinTheirBoundsAndTheBoxKeysSayThereIsNoBox() {
        ControllerConfig cc = ControllerConfig.load(Home.resolve("configs/controller.json"));
        HeightGoals goals = new HeightGoals(1.1, 1.3);
        HeightControl control = new HeightControl(0.05, 1.0, 1.4);
        SteeredTask steered = TestSupport.configs().height().steered("sphere", goals, control.min(), control.max());
        CatchEvaluation evaluation = CatchEvaluation.nominal(cc, EpisodeLimits.parse(Json.load(Home.resolve("configs/episode.json"))),
                LaunchDistribution.load(Home.resolve("configs/launch.json")), TestSupport.object("sphere"), steered.task());
        try (CatchLoopScene scene = new CatchLoopScene(new OdeSimulator(TestSupport.model(), TestSupport.simConfig()),
                evaluation, steered, 7, control, null)) {
            double first = ((Goal.Height) scene.goal()).height();
            assertEquals(goals.current(), first, 0, "before the first throw the plane shows the first goal");
            scene.apply(SceneCommand.GOAL_UP);
            assertEquals(first + 0.05, ((Goal.Height) scene.goal()).height(), 1e-12);
            assertEquals(1.35, goals.high(), 1e-12);
            scene.apply(SceneCommand.GOAL_UP);
            String note = scene.apply(SceneCommand.GOAL_UP);
            assertEquals(1.4, goals.high(), 1e-12, "stops at the upper bound");
            assertTrue(note.contains("upper bound"), note);
            for (int i = 0; i < 10; i++) {
                scene.apply(SceneCommand.GOAL_DOWN);
            }
            assertEquals(1.0, goals.low(), 1e-12, "stops at the lower bound");

            assertTrue(scene.apply(SceneCommand.GOAL_LEFT).contains("no box"));
            scene.advance(0.1);
            scene.apply(SceneCommand.RESET);
            assertEquals(0, scene.time(), 0, "reset starts the episode again");
            assertEquals("seed 7 (1 so far)", scene.status().get("episode"));
            scene.apply(SceneCommand.NEW_THROW);
            assertEquals("seed 8 (2 so far)", scene.status().get("episode"));
        }
    }
}
