package handsim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.math.Vec3;
import org.junit.jupiter.api.Test;

/** The camera's projection, without OpenGL. */
class CameraTest {

    /** Matrices are single precision (what OpenGL takes): ~1e-7 relative, far below a pixel. */
    static final double PIXEL_TOLERANCE = 1e-3;

    @Test
    void targetProjectsToTheImageCentreAndUpIsUp() {
        Camera c = new Camera();
        double[] centre = c.project(c.target, 960, 720);
        assertEquals(480, centre[0], PIXEL_TOLERANCE, "the look-at target is the image centre");
        assertEquals(360, centre[1], PIXEL_TOLERANCE);
        double[] above = c.project(c.target.plus(new Vec3(0, 0.1, 0)), 960, 720);
        assertTrue(above[1] < 360, "a point above the target appears higher in the image (smaller row)");
    }

    @Test
    void pointsBehindTheCameraDoNotProject() {
        Camera c = new Camera();
        Vec3 behind = c.eye().plus(c.eye().minus(c.target));
        assertNull(c.project(behind, 960, 720));
    }

    @Test
    void pointAtTheEdgeOfTheFieldOfViewLandsOnTheImageBorder() {
        // a point 1 m in front of the eye and tan(fov/2) m above the view axis sits on the top row
        Camera c = new Camera();
        c.pitch = 0;
        Vec3 forward = c.target.minus(c.eye()).normalized();
        Vec3 p = c.eye().plus(forward).plus(Vec3.Y.times(Math.tan(c.fovY / 2)));
        assertEquals(0, c.project(p, 960, 720)[1], PIXEL_TOLERANCE);
    }
}
