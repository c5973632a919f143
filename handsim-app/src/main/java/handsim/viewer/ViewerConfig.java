package handsim.viewer;

import handsim.config.Json;
import handsim.math.Vec3;
import java.nio.file.Path;
import java.util.List;

/**
 * Everything tunable about drawing and the interactive viewer, from {@code configs/viewer.json}.
 * Every field is required and validated; messages name the field and the value.
 */
public record ViewerConfig(Window window, CameraHome camera, Pacing pacing, Benchmark benchmark, Goals goals,
        Stage stage, Overlays overlays, Hud hud, Recording recording, Palette colours) {

    /**
     * Window size in pixels; vsync caps the frame rate at the display's refresh; while the
     * simulation falls behind real time, frames come no faster than {@code fpsWhenBehind}.
     */
    public record Window(int width, int height, boolean vsync, double fpsWhenBehind) {
    }

    /**
     * The camera's home framing (angles in radians) and how the mouse moves it: orbit angle per
     * pixel, pan per pixel as a fraction of the distance, zoom per scroll notch as a fraction,
     * and the rate (1/s) at which the follow mode's target catches up with the object.
     */
    public record CameraHome(Vec3 target, double yaw, double pitch, double distance, double fovY, double minDistance,
            double maxDistance, double orbitPerPixel, double panPerPixel, double zoomPerScroll, double followRate) {
    }

    /** The sim-time accumulator (see {@link handsim.scene.SimClock}) and the slow-motion speeds, real time first. */
    public record Pacing(double maxLagSeconds, double minChunkSeconds, double maxChunkSeconds, double singleStepSeconds,
            List<Double> slowMotion) {
        public Pacing {
            slowMotion = List.copyOf(slowMotion);
        }
    }

    /** {@code --benchmark-frames} counts frames only after drawing for {@code warmupSeconds}. */
    public record Benchmark(double warmupSeconds) {
    }

    /** Steps and bounds of the goal keys, and the size of the drawn height plane. */
    public record Goals(double heightStep, double heightMin, double heightMax, double planeHalfSize) {
    }

    /** The direction light travels (unit), the checkered floor, and the surface finish of a glTF export's materials. */
    public record Stage(Vec3 light, double floorHalfSize, double floorTile, double roughness) {
    }

    public record Overlays(double trailSeconds, double trailWidthPixels, double axisLength, double axisWidthPixels) {
    }

    public record Hud(int fontSizePixels, double noteSeconds) {
    }

    /**
     * Frames are recorded every 1/fps simulated seconds into a new folder under {@code folder}; a
     * glTF recording samples the world {@code gltfRate} times a simulated second into a file there.
     */
    public record Recording(int fps, double gltfRate, String folder) {
    }

    /** RGBA colours in [0, 1]; {@code axes} colours the first, second and third DOF of a joint. */
    public record Palette(float[] background, float[] floorLight, float[] floorDark, float[] skin, float[] palm,
            float[] object, float[] staticBox, float[] shadow, float[] goalPlane, float[] goalBox, float[] trail,
            List<float[]> axes, float[] hudPanel, float[] hudText, float[] hudLabel, float[] hudWarning) {
    }

    public static ViewerConfig load(Path file) {
        return parse(Json.load(file));
    }

    public static ViewerConfig parse(Json j) {
        j.allow("comment");
        Json w = j.get("window");
        w.allow("comment");
        Window window = new Window(w.integer("width", 64, 8192), w.integer("height", 64, 8192), w.bool("vsync", true),
                w.number("fpsWhenBehind", 1, 1000));
        Json c = j.get("camera");
        c.allow("comment");
        double minDistance = c.number("minDistance", 0.01, 100);
        double maxDistance = c.number("maxDistance", minDistance, 1000);
        CameraHome camera = new CameraHome(c.vec3("target"), Math.toRadians(c.number("yawDeg", -360, 360)),
                Math.toRadians(c.number("pitchDeg", -89, 89)), c.number("distance", minDistance, maxDistance),
                Math.toRadians(c.number("fovYDeg", 5, 150)), minDistance, maxDistance,
                Math.toRadians(c.number("orbitDegPerPixel", 1e-4, 10)), c.number("panPerPixel", 1e-6, 1),
                c.number("zoomPerScroll", 1e-3, 0.9), c.number("followRate", 0.01, 1000));
        Json p = j.get("pacing");
        p.allow("comment");
        double minChunk = p.number("minChunkSeconds", 1e-5, 1);
        List<Double> speeds = new java.util.ArrayList<>();
        for (Json s : p.array("slowMotion")) {
            double v = s.asNumber();
            if (!(v > 0 && v <= 100)) {
                throw s.error("a speed must be in (0, 100], got " + v);
            }
            speeds.add(v);
        }
        if (speeds.isEmpty()) {
            throw p.fieldError("slowMotion", "needs at least one speed (real time, 1.0, first)");
        }
        Pacing pacing = new Pacing(p.number("maxLagSeconds", 1e-3, 10), minChunk, p.number("maxChunkSeconds", minChunk, 1),
                p.number("singleStepSeconds", 1e-6, 1), speeds);
        Json b = j.get("benchmark");
        b.allow("comment");
        Benchmark benchmark = new Benchmark(b.number("warmupSeconds", 0, 60));
        Json g = j.get("goals");
        g.allow("comment");
        double heightMin = g.number("heightMin", 0.01, 10);
        Goals goals = new Goals(g.number("heightStep", 1e-3, 1), heightMin, g.number("heightMax", heightMin + 1e-3, 10),
                g.number("planeHalfSize", 0.01, 10));
        Json st = j.get("scene");
        st.allow("comment");
        Vec3 light = st.vec3("light");
        if (!(light.y() < -1e-3) || !light.isFinite()) {
            throw st.fieldError("light", "must point downward (y < 0) to cast shadows on the floor, got " + light);
        }
        Stage stage = new Stage(light.normalized(), st.number("floorHalfSize", 0.1, 100), st.number("floorTile", 0.01, 10),
                st.number("roughness", 0, 1));
        Json o = j.get("overlays");
        Overlays overlays = new Overlays(o.number("trailSeconds", 0.05, 60), o.number("trailWidthPixels", 0.5, 20),
                o.number("axisLength", 1e-3, 1), o.number("axisWidthPixels", 0.5, 20));
        Json h = j.get("hud");
        Hud hud = new Hud(h.integer("fontSizePixels", 6, 96), h.number("noteSeconds", 0.1, 600));
        Json r = j.get("recording");
        r.allow("comment");
        Recording recording = new Recording(r.integer("fps", 1, 240), r.number("gltfRate", 1, 240), r.string("folder"));
        Json k = j.get("colours");
        List<float[]> axes = new java.util.ArrayList<>();
        for (Json a : k.array("axes")) {
            axes.add(colour(a));
        }
        if (axes.size() != 3) {
            throw k.fieldError("axes", "needs 3 colours (first, second, third DOF of a joint), got " + axes.size());
        }
        Palette palette = new Palette(colour(k, "background"), colour(k, "floorLight"), colour(k, "floorDark"),
                colour(k, "skin"), colour(k, "palm"), colour(k, "object"), colour(k, "staticBox"), colour(k, "shadow"),
                colour(k, "goalPlane"), colour(k, "goalBox"), colour(k, "trail"), axes, colour(k, "hudPanel"),
                colour(k, "hudText"), colour(k, "hudLabel"), colour(k, "hudWarning"));
        for (Json node : new Json[] {w, c, p, b, g, st, o, h, r, k, j}) {
            node.requireNoUnknownFields();
        }
        return new ViewerConfig(window, camera, pacing, benchmark, goals, stage, overlays, hud, recording, palette);
    }

    private static float[] colour(Json parent, String name) {
        return colour(parent.get(name));
    }

    private static float[] colour(Json v) {
        double[] rgba = v.asNumbers(4);
        float[] out = new float[4];
        for (int i = 0; i < 4; i++) {
            if (!(rgba[i] >= 0 && rgba[i] <= 1)) {
                throw v.error("colour components must be in [0, 1], got " + rgba[i]);
            }
            out[i] = (float) rgba[i];
        }
        return out;
    }
}
