package handsim.viewer;

import handsim.math.Vec3;

/**
 * An orbit camera: it looks at {@code target} from {@code distance} metres, turned by
 * {@code yaw} about the world's up axis (y) and raised by {@code pitch}. Matrices are
 * column-major float[16], as OpenGL takes them. Pure maths, no OpenGL: tests use it to predict
 * where a world point lands on the image.
 */
public final class Camera {

    /** Default framing: arm, hand and the object's flight, seen from the front-right and above. */
    public static final Vec3 DEFAULT_TARGET = new Vec3(0.05, 0.85, 0.25);
    public static final double DEFAULT_YAW = Math.toRadians(40);
    public static final double DEFAULT_PITCH = Math.toRadians(10);
    public static final double DEFAULT_DISTANCE = 1.55;
    public static final double DEFAULT_FOV_Y = Math.toRadians(45);
    static final double NEAR = 0.05, FAR = 30;

    public Vec3 target = DEFAULT_TARGET;
    public double yaw = DEFAULT_YAW;
    public double pitch = DEFAULT_PITCH;
    public double distance = DEFAULT_DISTANCE;
    public double fovY = DEFAULT_FOV_Y;

    /** Back to the default framing. */
    public void reset() {
        target = DEFAULT_TARGET;
        yaw = DEFAULT_YAW;
        pitch = DEFAULT_PITCH;
        distance = DEFAULT_DISTANCE;
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
