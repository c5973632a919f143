package handsim.app;

import handsim.cards.sim.SoftBody;
import handsim.cards.sim.Trajectory;
import handsim.config.Home;
import handsim.config.Json;
import handsim.math.Vec3;
import handsim.viewer.Camera;
import handsim.viewer.SurfaceMesh;
import handsim.viewer.ViewerConfig;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * How a card sleight is drawn (configs/cards/views.json): its camera and the colour of each
 * body, and a recorded frame's surfaces in the viewer's frame, cards drawn as slabs of their
 * thickness ({@link CardSlab}) so that a stack's layers show from the side.
 */
final class CardViews {

    /** A sleight's view: the camera's home and colours by body name ("card", "fingertip" for the rest). */
    record View(ViewerConfig.CameraHome camera, Map<String, float[]> colours) {

        float[] colour(Trajectory.Surface s) {
            float[] c = colours.get(s.name());
            return c != null ? c : colours.get(s.kind() == SoftBody.Kind.CARD ? "card" : "fingertip");
        }
    }

    private CardViews() {
    }

    /** The view of {@code sleight} from configs/cards/views.json, the orbit speeds from the viewer's config. */
    static View of(String sleight, ViewerConfig viewer) {
        Json root = Json.load(Home.resolve("configs/cards/views.json"));
        root.allow("comment");
        if (!root.has(sleight)) {
            throw root.error("no view of the sleight \"" + sleight + "\"");
        }
        Json v = root.get(sleight);
        v.allow("comment");
        Json cam = v.get("camera");
        double[] t = cam.numbers("target", 3);
        ViewerConfig.CameraHome h = viewer.camera();
        double distance = cam.number("distance", 0.01, 10);
        ViewerConfig.CameraHome home = new ViewerConfig.CameraHome(viewerFrame(t[0], t[1], t[2]), Math.toRadians(cam.number("yawDeg", -360, 360)),
                Math.toRadians(cam.number("pitchDeg", -89, 89)), distance, Math.toRadians(cam.number("fovYDeg", 5, 120)), 0.2 * distance,
                20 * distance, h.orbitPerPixel(), h.panPerPixel(), h.zoomPerScroll(), h.followRate());
        cam.requireNoUnknownFields();
        Json c = v.get("colours");
        Map<String, float[]> colours = new LinkedHashMap<>();
        for (String name : c.fieldNames()) {
            double[] rgb = c.numbers(name, 3);
            for (double x : rgb) {
                if (!(x >= 0 && x <= 1)) {
                    throw c.fieldError(name, "colour components must be in [0, 1], got " + java.util.Arrays.toString(rgb));
                }
            }
            colours.put(name, new float[] {(float) rgb[0], (float) rgb[1], (float) rgb[2], 1});
        }
        for (String needed : List.of("card", "fingertip")) {
            if (!colours.containsKey(needed)) {
                throw v.fieldError("colours", "needs \"" + needed + "\" for the bodies not named");
            }
        }
        v.requireNoUnknownFields();
        return new View(home, colours);
    }

    static Camera camera(View view) {
        return new Camera(view.camera());
    }

    /** Card scene (x, y, z up) to the viewer's frame (x, z, −y). */
    static Vec3 viewerFrame(double x, double y, double z) {
        return new Vec3(x, z, -y);
    }

    /** A frame's surfaces in the viewer's frame, coloured by the view, cards as slabs. */
    static List<SurfaceMesh> surfaces(Trajectory trajectory, Trajectory.Frame frame, View view) {
        List<SurfaceMesh> out = new ArrayList<>();
        for (int s = 0; s < trajectory.surfaces().size(); s++) {
            Trajectory.Surface surface = trajectory.surfaces().get(s);
            double[] p = frame.positions().get(s);
            boolean card = surface.kind() == SoftBody.Kind.CARD;
            CardSlab.Mesh m = card && surface.thickness() > 0 ? CardSlab.of(p, surface.triangles(), surface.thickness())
                    : new CardSlab.Mesh(p, surface.triangles());
            float[] v = new float[m.positions().length];
            for (int i = 0; i < v.length / 3; i++) {
                v[3 * i] = (float) m.positions()[3 * i];
                v[3 * i + 1] = (float) m.positions()[3 * i + 2];
                v[3 * i + 2] = (float) -m.positions()[3 * i + 1];
            }
            out.add(new SurfaceMesh(v, m.triangles(), view.colour(surface), card));
        }
        return out;
    }
}
