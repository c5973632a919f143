package handsim.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** Real-time pacing of a scene by the run's accumulator, without its thread (update() by hand). */
@Tag("fast")
class LiveRunTest {

    static final double FRAME = 1 / 60.0, MAX_LAG = 0.1, MIN_CHUNK = 0.004, MAX_CHUNK = 0.017;

    private static LiveRun run(FakeScene scene, List<String> log) {
        return new LiveRun(scene, new SimClock(MAX_LAG), MIN_CHUNK, MAX_CHUNK, log::add);
    }

    /** What the run's thread does when {@code wall} seconds have passed: passes until nothing more is owed. */
    private static void elapse(LiveRun run, double wall) {
        run.update(wall);
        while (run.update(0)) {
            // catching up, a chunk at a time
        }
    }

    @Test
    void simulatedTimeFollowsWallTimeWithinOneTickWhateverTheFrameRate() {
        for (double frame : new double[] {1 / 30.0, FRAME, 1 / 144.0}) {
            FakeScene scene = new FakeScene();
            LiveRun run = run(scene, new ArrayList<>());
            double wall = 0;
            for (int i = 0; i < 600; i++) {
                elapse(run, frame);
                wall += frame;
                // the scene lags by less than the minimum chunk and leads by less than one tick
                assertTrue(scene.time() > wall - MIN_CHUNK - FakeScene.TICK && scene.time() < wall + FakeScene.TICK,
                        "frame " + frame + ": sim " + scene.time() + " vs wall " + wall);
            }
            assertEquals(1.0, run.simulatedSeconds() / run.wallSeconds(), 0.01, "real-time factor at frame " + frame);
            assertEquals(1.0, run.latest().realTimeFactor(), 0.02, "the published factor");
        }
    }

    @Test
    void slowMotionAndPauseScaleTheSimulatedTime() {
        FakeScene scene = new FakeScene();
        LiveRun run = run(scene, new ArrayList<>());
        run.setSpeed(0.25);
        for (int i = 0; i < 240; i++) {
            elapse(run, FRAME);
        }
        assertEquals(1.0, scene.time(), MIN_CHUNK + FakeScene.TICK, "4 wall seconds at 1/4 speed");
        assertEquals(0.25, run.latest().speed());
        run.setPaused(true);
        run.update(FRAME);
        double paused = scene.time();
        for (int i = 0; i < 60; i++) {
            elapse(run, FRAME);
        }
        assertEquals(paused, scene.time(), 0, "nothing moves while paused");
        assertTrue(run.latest().paused());
        run.step(FakeScene.TICK);
        run.update(FRAME);
        assertEquals(paused + FakeScene.TICK, scene.time(), 1e-12, "a single step advances exactly one tick");
    }

    @Test
    void aSlowSceneFallsBehindInsteadOfSpiralling() {
        // one pass advances at most MAX_CHUNK; a 1 s stall owes at most MAX_LAG, not a second
        FakeScene scene = new FakeScene();
        LiveRun run = run(scene, new ArrayList<>());
        run.update(1.0);
        assertEquals(MAX_CHUNK, scene.time(), FakeScene.TICK);
        assertTrue(run.behind(), "owing more than a chunk: behind real time");
        for (int i = 0; i < 20; i++) {
            run.update(0);
        }
        assertEquals(MAX_LAG, scene.time(), FakeScene.TICK, "the lag is paid back, the rest of the stall is dropped");
        assertFalse(run.behind(), "caught up");
    }

    @Test
    void commandsRunOnTheRunsPassAndTheirNotesAreLoggedAndShown() {
        FakeScene scene = new FakeScene();
        List<String> log = new ArrayList<>();
        LiveRun run = run(scene, log);
        run.command(SceneCommand.GOAL_UP);
        assertTrue(scene.commands.isEmpty(), "queued until the run's next pass");
        run.update(FRAME);
        assertEquals(List.of(SceneCommand.GOAL_UP), scene.commands);
        assertEquals("did GOAL_UP", run.pollNote());
        assertEquals(List.of("did GOAL_UP"), log);
    }

    @Test
    void aFailingSceneIsReportedAndPausedNotFatal() {
        FakeScene scene = new FakeScene();
        List<String> log = new ArrayList<>();
        LiveRun run = run(scene, log);
        scene.failNextAdvance = new IllegalStateException("boom");
        run.update(FRAME);
        assertTrue(run.latest().paused());
        String note = run.pollNote();
        assertNotNull(note);
        assertTrue(note.contains("boom"), note);
        run.close();
        assertTrue(scene.closed, "the run owns its scene");
    }

    @Test
    void aResetIsNotCountedAsNegativeTime() {
        FakeScene scene = new FakeScene();
        LiveRun run = run(scene, new ArrayList<>());
        for (int i = 0; i < 30; i++) {
            run.update(FRAME);
        }
        double before = run.simulatedSeconds();
        run.command(SceneCommand.RESET);
        run.update(FRAME);
        assertTrue(run.simulatedSeconds() >= before, "simulated seconds only grow");
        assertTrue(scene.time() < 0.05, "the scene went back to its start");
    }
}
