package handsim.viewer;

import handsim.math.Vec3;

/**
 * An orbit camera: it looks at {@code target} from {@code distance} metres, turned by
 * {@code yaw} about the world's up axis (y) and raised by {@code pitch}. The mouse orbits, pans
 * and zooms it; {@link #reset()} returns to the home framing of {@code configs/viewer.json}.
 * Matrices are column-major float[16], as OpenGL takes them. Pure maths, no OpenGL: tests use it
 * to predict where a world point lands on the image.
 */
public final class Camera {

    static final double NEAR = 0.05, FAR = 30;
    /** Pitch stays short of straight up or down, where the look-at frame is undefined. */
    static final double MAX_PITCH = Math.toRadians(89);

    private final ViewerConfig.CameraHome home;
    public Vec3 target;
    public double yaw;
    public double pitch;
    public double distance;
    public double fovY;

    public Camera(ViewerConfig.CameraHome home) {
        this.home = home;
        reset();
    }

    /** Back to the home framing. */
    public void reset() {
        target = home.target();
        yaw = home.yaw();
        pitch = home.pitch();
        distance = home.distance();
        fovY = home.fovY();
    }

    /** Turns the camera around its target by a mouse drag of (dx, dy) pixels (drag right: the scene turns right). */
    public void orbit(double dx, double dy) {
        yaw -= dx * home.orbitPerPixel();
        pitch = Math.max(-MAX_PITCH, Math.min(MAX_PITCH, pitch + dy * home.orbitPerPixel()));
    }

    /** Slides the target in the image plane by a drag of (dx, dy) pixels: the scene follows the mouse. */
    public void pan(double dx, double dy) {
        Vec3 forward = target.minus(eye()).normalized();
        Vec3 right = forward.cross(Vec3.Y).normalized();
        Vec3 up = right.cross(forward);
        double k = distance * home.panPerPixel();
        target = target.plus(right.times(-dx * k)).plus(up.times(dy * k));
    }

    /** Moves toward the target by {@code notches} scroll steps (negative: away), within the distance bounds. */
    public void zoom(double notches) {
        distance = Math.max(home.minDistance(), Math.min(home.maxDistance(),
                distance * Math.pow(1 - home.zoomPerScroll(), notches)));
    }

    /** Eases the target toward {@code point} over {@code dt} seconds (exponential, at the configured rate). */
    public void follow(Vec3 point, double dt) {
        double a = 1 - Math.exp(-home.followRate() * Math.max(0, dt));
        target = target.lerp(point, a);
    }

    /** The camera's position in the world. */
    public Vec3 eye() {
        double c = Math.cos(pitch);
        return target.plus(new Vec3(c * Math.sin(yaw), Math.sin(pitch), c * Math.cos(yaw)).times(distance));
    }

    /** World to camera (look-at). */
    public float[] view() {
        Vec3 eye = eye();
        Vec3 f = target.minus(eye).normalized();
        Vec3 s = f.cross(Vec3.Y).normalized();
        Vec3 u = s.cross(f);
        return new float[] {
            (float) s.x(), (float) u.x(), (float) -f.x(), 0,
            (float) s.y(), (float) u.y(), (float) -f.y(), 0,
            (float) s.z(), (float) u.z(), (float) -f.z(), 0,
            (float) -s.dot(eye), (float) -u.dot(eye), (float) f.dot(eye), 1};
    }

    /** Perspective projection for an image of the given aspect ratio (width / height). */
    public float[] projection(double aspect) {
        double t = 1 / Math.tan(fovY / 2);
        return new float[] {
            (float) (t / aspect), 0, 0, 0,
            0, (float) t, 0, 0,
            0, 0, (float) ((FAR + NEAR) / (NEAR - FAR)), -1,
            0, 0, (float) (2 * FAR * NEAR / (NEAR - FAR)), 0};
    }

    /**
     * Pixel coordinates (x right, y down from the top-left corner) where {@code world} appears
     * in a {@code width} x {@code height} image; null if it is behind the camera.
     */
    public double[] project(Vec3 world, int width, int height) {
        float[] v = view(), p = projection((double) width / height);
        double[] eyeSpace = transform(v, world.x(), world.y(), world.z(), 1);
        double[] clip = transform(p, eyeSpace[0], eyeSpace[1], eyeSpace[2], eyeSpace[3]);
        if (clip[3] <= 0) {
            return null;
        }
        double nx = clip[0] / clip[3], ny = clip[1] / clip[3];
        return new double[] {(nx + 1) / 2 * width, (1 - ny) / 2 * height};
    }

    private static double[] transform(float[] m, double x, double y, double z, double w) {
        double[] out = new double[4];
        for (int r = 0; r < 4; r++) {
            out[r] = m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r] * w;
        }
        return out;
    }
}
