package handsim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.glfw.GLFW.*;

import handsim.AppTestSupport;
import handsim.TestSupport;
import handsim.scene.FakeScene;
import handsim.scene.LiveRun;
import handsim.scene.SimClock;
import handsim.scene.SceneCommand;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** Keys and mouse, without a window: GLFW events in, run commands, camera moves and requests out. */
@Tag("fast")
class ViewerControlsTest {

    private FakeScene scene;
    private LiveRun run;
    private Camera camera;
    private ViewerControls controls;
    private ViewerConfig config;

    @BeforeEach
    void setUp() {
        config = AppTestSupport.viewerConfig();
        scene = new FakeScene();
        run = new LiveRun(scene, new SimClock(config.pacing().maxLagSeconds()), config.pacing().minChunkSeconds(),
                config.pacing().maxChunkSeconds(), s -> { });
        camera = new Camera(config.camera());
        controls = new ViewerControls(run, camera, config.pacing());
    }

    private void press(int key) {
        controls.key(key, GLFW_PRESS, 0);
        run.update(0);
    }

    @Test
    void everyActionHasItsOwnKeyAndEverySceneCommandAKey() {
        Set<Integer> keys = new HashSet<>();
        Set<SceneCommand> commands = new HashSet<>();
        for (ViewerAction a : ViewerAction.values()) {
            assertTrue(keys.add(a.key), "key of " + a + " is bound twice");
            assertEquals(a, ViewerAction.forKey(a.key));
            if (a.command != null) {
                commands.add(a.command);
            }
        }
        assertEquals(Set.of(SceneCommand.values()), commands, "the help lists a key for every scene command");
    }

    @Test
    void sceneKeysReachTheSceneThroughTheRun() {
        int[] keys = {GLFW_KEY_R, GLFW_KEY_N, GLFW_KEY_O, GLFW_KEY_T, GLFW_KEY_C, GLFW_KEY_UP, GLFW_KEY_DOWN, GLFW_KEY_LEFT,
            GLFW_KEY_RIGHT, GLFW_KEY_PAGE_UP, GLFW_KEY_PAGE_DOWN};
        for (int k : keys) {
            press(k);
        }
        assertEquals(List.of(SceneCommand.RESET, SceneCommand.NEW_THROW, SceneCommand.NEXT_OBJECT, SceneCommand.NEXT_TASK,
                SceneCommand.TOGGLE_CONTROLLER, SceneCommand.GOAL_UP, SceneCommand.GOAL_DOWN, SceneCommand.GOAL_LEFT,
                SceneCommand.GOAL_RIGHT, SceneCommand.GOAL_FARTHER, SceneCommand.GOAL_NEARER), scene.commands);
    }

    @Test
    void holdingAGoalKeyRepeatsButHoldingAToggleDoesNot() {
        controls.key(GLFW_KEY_UP, GLFW_PRESS, 0);
        controls.key(GLFW_KEY_UP, GLFW_REPEAT, 0);
        controls.key(GLFW_KEY_UP, GLFW_RELEASE, 0);
        controls.key(GLFW_KEY_N, GLFW_PRESS, 0);
        controls.key(GLFW_KEY_N, GLFW_REPEAT, 0);
        run.update(0);
        assertEquals(List.of(SceneCommand.GOAL_UP, SceneCommand.GOAL_UP, SceneCommand.NEW_THROW), scene.commands);
    }

    @Test
    void pauseStepAndSlowMotionDriveTheRunsClock() {
        press(GLFW_KEY_SPACE);
        assertTrue(run.latest().paused());
        press(GLFW_KEY_SPACE);
        assertFalse(run.latest().paused());
        List<Double> speeds = new ArrayList<>();
        for (int i = 0; i < config.pacing().slowMotion().size(); i++) {
            press(GLFW_KEY_S);
            speeds.add(run.latest().speed());
        }
        List<Double> expected = new ArrayList<>(config.pacing().slowMotion().subList(1, speeds.size()));
        expected.add(config.pacing().slowMotion().get(0));
        assertEquals(expected, speeds, "S cycles through the slow-motion speeds back to real time");
        double t = scene.time();
        press(GLFW_KEY_PERIOD);
        assertTrue(run.latest().paused(), "a single step pauses");
        assertEquals(t + FakeScene.TICK, scene.time(), 1e-12, "and advances by one controller period");
    }

    @Test
    void viewerKeysToggleOverlaysAndRequestPictures() {
        boolean trail = controls.trail;
        press(GLFW_KEY_P);
        assertNotEquals(trail, controls.trail);
        press(GLFW_KEY_J);
        assertTrue(controls.axes);
        press(GLFW_KEY_H);
        assertTrue(controls.help);
        press(GLFW_KEY_I);
        assertTrue(controls.screenshotRequested);
        press(GLFW_KEY_M);
        assertTrue(controls.recordToggleRequested);
        press(GLFW_KEY_G);
        assertTrue(controls.gltfToggleRequested);
        press(GLFW_KEY_ESCAPE);
        assertTrue(controls.quitRequested);
        assertTrue(scene.commands.isEmpty(), "none of these is the scene's business");
    }

    @Test
    void mouseOrbitsPansZoomsAndVResetsTheCamera() {
        double yaw = camera.yaw;
        controls.cursor(100, 100);
        controls.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
        controls.cursor(150, 100);
        assertEquals(yaw - 50 * config.camera().orbitPerPixel(), camera.yaw, 1e-12, "left drag orbits");
        controls.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
        controls.cursor(300, 300);
        assertEquals(yaw - 50 * config.camera().orbitPerPixel(), camera.yaw, 1e-12, "no button, no move");

        var target = camera.target;
        controls.mouseButton(GLFW_MOUSE_BUTTON_RIGHT, GLFW_PRESS, 0);
        controls.cursor(320, 300);
        assertNotEquals(target, camera.target, "right drag pans");
        controls.mouseButton(GLFW_MOUSE_BUTTON_RIGHT, GLFW_RELEASE, 0);

        double d = camera.distance;
        controls.scroll(2);
        assertTrue(camera.distance < d, "wheel forward zooms in");

        press(GLFW_KEY_F);
        assertTrue(controls.follow);
        press(GLFW_KEY_V);
        assertFalse(controls.follow, "resetting the camera stops following");
        assertEquals(config.camera().target(), camera.target);
        assertEquals(config.camera().distance(), camera.distance);
        assertNotNull(run.latest());
    }

    @Test
    void speedsReadAsFractions() {
        assertEquals("1 ×", Hud.speed(1));
        assertEquals("1/4 ×", Hud.speed(0.25));
        assertEquals("1/10 ×", Hud.speed(0.1));
        assertEquals("0.3 ×", Hud.speed(0.3));
    }
}
