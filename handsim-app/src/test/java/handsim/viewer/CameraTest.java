package handsim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.AppTestSupport;
import handsim.TestSupport;
import handsim.math.Vec3;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The camera's projection and mouse moves, without OpenGL. */
@Tag("fast")
class CameraTest {

    /** Matrices are single precision (what OpenGL takes): ~1e-7 relative, far below a pixel. */
    static final double PIXEL_TOLERANCE = 1e-3;

    @Test
    void targetProjectsToTheImageCentreAndUpIsUp() {
        Camera c = new Camera(AppTestSupport.viewerConfig().camera());
        double[] centre = c.project(c.target, 960, 720);
        assertEquals(480, centre[0], PIXEL_TOLERANCE, "the look-at target is the image centre");
        assertEquals(360, centre[1], PIXEL_TOLERANCE);
        double[] above = c.project(c.target.plus(new Vec3(0, 0.1, 0)), 960, 720);
        assertTrue(above[1] < 360, "a point above the target appears higher in the image (smaller row)");
    }

    @Test
    void pointsBehindTheCameraDoNotProject() {
        Camera c = new Camera(AppTestSupport.viewerConfig().camera());
        Vec3 behind = c.eye().plus(c.eye().minus(c.target));
        assertNull(c.project(behind, 960, 720));
    }

    @Test
    void pointAtTheEdgeOfTheFieldOfViewLandsOnTheImageBorder() {
        // a point 1 m in front of the eye and tan(fov/2) m above the view axis sits on the top row
        Camera c = new Camera(AppTestSupport.viewerConfig().camera());
        c.pitch = 0;
        Vec3 forward = c.target.minus(c.eye()).normalized();
        Vec3 p = c.eye().plus(forward).plus(Vec3.Y.times(Math.tan(c.fovY / 2)));
        assertEquals(0, c.project(p, 960, 720)[1], PIXEL_TOLERANCE);
    }

    @Test
    void panningMovesTheTargetWithTheMouse() {
        // a drag of dx pixels moves the target sideways by dx * panPerPixel * distance: a point
        // that stays fixed in the world appears to move the same way as the mouse
        Camera c = new Camera(AppTestSupport.viewerConfig().camera());
        Vec3 world = c.target;
        double before = c.project(world, 960, 720)[0];
        c.pan(40, 0);
        double after = c.project(world, 960, 720)[0];
        assertTrue(after > before + 5, "the scene follows a rightward drag: " + before + " -> " + after);
        assertEquals(40 * AppTestSupport.viewerConfig().camera().panPerPixel() * c.distance, c.target.distance(world), 1e-12);
    }

    @Test
    void orbitKeepsTheTargetAndDistanceAndClampsThePitch() {
        Camera c = new Camera(AppTestSupport.viewerConfig().camera());
        Vec3 target = c.target;
        double d = c.eye().distance(target);
        c.orbit(200, 0);
        assertEquals(d, c.eye().distance(target), 1e-12, "orbiting turns around the target");
        assertEquals(target, c.target);
        c.orbit(0, 1e6);
        assertEquals(Camera.MAX_PITCH, c.pitch, 1e-12, "pitch stops short of straight down");
    }

    @Test
    void zoomStaysWithinItsBoundsAndResetReturnsHome() {
        var home = AppTestSupport.viewerConfig().camera();
        Camera c = new Camera(home);
        c.zoom(1);
        assertEquals(home.distance() * (1 - home.zoomPerScroll()), c.distance, 1e-12, "one notch in");
        c.zoom(1000);
        assertEquals(home.minDistance(), c.distance, 1e-12);
        c.zoom(-1000);
        assertEquals(home.maxDistance(), c.distance, 1e-12);
        c.orbit(50, 50);
        c.reset();
        assertEquals(home.distance(), c.distance);
        assertEquals(home.yaw(), c.yaw);
        assertEquals(home.target(), c.target);
    }

    @Test
    void followEasesTowardThePointAtTheConfiguredRate() {
        var home = AppTestSupport.viewerConfig().camera();
        Camera c = new Camera(home);
        Vec3 start = c.target, point = start.plus(new Vec3(1, 0, 0));
        double dt = 0.05;
        c.follow(point, dt);
        // exponential approach: the remaining distance shrinks by exp(-rate dt)
        assertEquals(Math.exp(-home.followRate() * dt), c.target.distance(point), 1e-12);
    }
}
