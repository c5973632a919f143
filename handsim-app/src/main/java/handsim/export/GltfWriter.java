package handsim.export;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.kin.Frame;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.mesh.Detail;
import handsim.mesh.ShapeMeshes;
import handsim.mesh.Surface;
import handsim.mesh.TriangleMesh;
import handsim.model.Body;
import handsim.model.HandModel;
import handsim.model.Shape;
import handsim.sim.WorldSnapshot;
import handsim.task.Goal;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import java.util.function.IntFunction;

/**
 * A {@link MotionClip} as glTF 2.0: the arm and hand as a node hierarchy that follows the model's
 * bodies (a node per body, named after it, at its joint anchor, at rest in the model's zero
 * configuration), each with the mesh of its shapes ({@link ShapeMeshes}, as the viewer draws
 * them); the object as a node of its own; optionally the floor, the goal and a camera. One
 * animation holds every body's and the object's translation and rotation (linear), sampled at
 * the clip's times; what appears and disappears (an object of another size after a reset, a
 * static box, the goal) has a step-interpolated scale. Metres, y up, as glTF wants; colours
 * are the viewer's, converted from sRGB to glTF's linear factors.
 */
final class GltfWriter {

    private final MotionClip clip;
    private final ExportOptions options;
    private final GltfDocument doc;
    private final JsonNodeFactory f = JsonNodeFactory.instance;
    private int times;

    private GltfWriter(MotionClip clip, ExportOptions options) {
        this.clip = clip;
        this.options = options;
        this.doc = new GltfDocument(options.roughness());
    }

    static GltfDocument.Gltf build(MotionClip clip, ExportOptions options) {
        return new GltfWriter(clip, options).build();
    }

    private GltfDocument.Gltf build() {
        if (clip.samples().size() < 2) {
            throw new IllegalArgumentException("an animation needs at least two samples, got " + clip.samples().size());
        }
        times = timeAccessor();
        List<Integer> scene = new ArrayList<>();
        scene.add(arm());
        scene.add(object());
        scene.addAll(staticBoxes());
        if (options.goal()) {
            scene.addAll(goals());
        }
        if (options.floor()) {
            scene.add(floor());
        }
        options.camera().ifPresent(c -> scene.add(camera(c)));
        return doc.finish(clip.title(), scene);
    }

    // ---- the arm and hand -----------------------------------------------------------------

    /** A node named after the model holding the body hierarchy; returns its index. */
    private int arm() {
        HandModel model = clip.model();
        int group = node(model.name());
        int[] bodyNode = new int[model.bodyCount()];
        for (Body b : model.bodies()) {
            int n = node(b.name());
            bodyNode[b.index()] = n;
            Vec3 parentOrigin = b.parent() < 0 ? Vec3.ZERO : model.bodies().get(b.parent()).origin();
            ObjectNode node = doc.nodeObject(n);
            node.set("translation", vector(b.origin().minus(parentOrigin)));
            if (!b.shapes().isEmpty()) {
                node.put("mesh", mesh(b.name(), ShapeMeshes.of(b.shapes(), Detail.FINE),
                        Surface.of(b) == Surface.PALM ? material("palm", options.colours().palm(), false)
                                : material("skin", options.colours().skin(), false)));
            }
            addChild(b.parent() < 0 ? group : bodyNode[b.parent()], n);
            // the body's frame relative to its parent's: the node's local transform
            int parent = b.parent();
            animate(n, i -> {
                MotionClip.Sample s = clip.samples().get(i);
                return relative(parent < 0 ? Frame.IDENTITY : s.body(parent), s.body(b.index()));
            });
        }
        return group;
    }

    private static Frame relative(Frame parent, Frame child) {
        return new Frame(parent.pointFromWorld(child.origin()), parent.rotation().conjugate().mul(child.rotation()));
    }

    // ---- the object -----------------------------------------------------------------------

    /**
     * The object's node, named after it ("object" if the run had several kinds), moved as its
     * centre of mass and turned as it is. Each object the run had (a seed varies its size; the
     * viewer may switch objects) is a mesh: on the node itself if there is one, else on a child
     * per object ("can 1", "can 2", ...) shown only while that one is in the world.
     */
    private int object() {
        List<MotionClip.Sample> samples = clip.samples();
        List<List<Shape>> sizes = new ArrayList<>();
        List<String> names = new ArrayList<>();
        for (MotionClip.Sample s : samples) {
            if (s.objectSpec() != null && !sizes.contains(s.objectSpec().shapes())) {
                sizes.add(s.objectSpec().shapes());
                names.add(s.objectSpec().name());
            }
        }
        String name = names.stream().distinct().count() == 1 ? names.get(0) : "object";
        int n = node(name);
        int material = material("object", options.colours().object(), false);
        // while no object is in the world the node holds the nearest pose it had
        Frame[] held = new Frame[samples.size()];
        Frame last = null;
        for (int i = 0; i < samples.size(); i++) {
            last = samples.get(i).objectFrame() != null ? samples.get(i).objectFrame() : last;
            held[i] = last;
        }
        for (int i = samples.size() - 1; i >= 0; i--) {
            last = held[i] != null ? held[i] : last;
            held[i] = last != null ? last : Frame.IDENTITY;
        }
        animate(n, i -> held[i]);
        boolean alwaysThere = samples.stream().allMatch(s -> s.objectSpec() != null);
        if (sizes.size() == 1 && alwaysThere) {
            doc.nodeObject(n).put("mesh", mesh(name, ShapeMeshes.of(sizes.get(0), Detail.FINE), material));
            return n;
        }
        for (int k = 0; k < sizes.size(); k++) {
            List<Shape> shapes = sizes.get(k);
            String sizeName = names.get(k) + " " + (k + 1);
            int child = node(sizeName);
            doc.nodeObject(child).put("mesh", mesh(sizeName, ShapeMeshes.of(shapes, Detail.FINE), material));
            addChild(n, child);
            stepChannel(child, "scale", s -> s.objectSpec() != null && s.objectSpec().shapes().equals(shapes) ? new Vec3(1, 1, 1) : Vec3.ZERO);
        }
        return n;
    }

    // ---- the stage ------------------------------------------------------------------------

    /** A node per static box the run had, a unit cube scaled to its size while it is in the world. */
    private List<Integer> staticBoxes() {
        List<WorldSnapshot.StaticBox> boxes = new ArrayList<>();
        clip.samples().forEach(s -> s.boxes().stream().filter(b -> !boxes.contains(b)).forEach(boxes::add));
        List<Integer> out = new ArrayList<>();
        for (int k = 0; k < boxes.size(); k++) {
            WorldSnapshot.StaticBox box = boxes.get(k);
            int n = node("box " + (k + 1));
            ObjectNode node = doc.nodeObject(n);
            node.set("translation", vector(box.center()));
            node.set("scale", vector(box.size()));
            node.put("mesh", mesh("box", ShapeMeshes.box(Vec3.ZERO, new Vec3(1, 1, 1)),
                    material("static box", options.colours().staticBox(), false)));
            if (!clip.samples().stream().allMatch(s -> s.boxes().contains(box))) {
                stepChannel(n, "scale", s -> s.boxes().contains(box) ? box.size() : Vec3.ZERO);
            }
            out.add(n);
        }
        return out;
    }

    /** The goal as the viewer draws it: a height as a translucent plane, a box as a translucent box; each shown while it is the goal. */
    private List<Integer> goals() {
        List<Integer> out = new ArrayList<>();
        List<MotionClip.Sample> samples = clip.samples();
        if (samples.stream().anyMatch(s -> s.goal() instanceof Goal.Height)) {
            int n = node("goal plane");
            doc.nodeObject(n).put("mesh", mesh("goal plane", ShapeMeshes.square(options.goalPlaneHalfSize()),
                    material("goal plane", options.colours().goalPlane(), true)));
            stepChannel(n, "translation", s -> s.goal() instanceof Goal.Height h
                    ? new Vec3(h.center().x(), h.height(), h.center().z()) : Vec3.ZERO);
            stepChannel(n, "scale", s -> s.goal() instanceof Goal.Height ? new Vec3(1, 1, 1) : Vec3.ZERO);
            out.add(n);
        }
        if (samples.stream().anyMatch(s -> s.goal() instanceof Goal.Box)) {
            int n = node("goal box");
            doc.nodeObject(n).put("mesh", mesh("goal box", ShapeMeshes.box(Vec3.ZERO, new Vec3(1, 1, 1)),
                    material("goal box", options.colours().goalBox(), false)));
            stepChannel(n, "translation", s -> s.goal() instanceof Goal.Box b ? b.center() : Vec3.ZERO);
            stepChannel(n, "scale", s -> s.goal() instanceof Goal.Box b ? b.size() : Vec3.ZERO);
            out.add(n);
        }
        return out;
    }

    /** The checkered floor at the ground's height: one mesh, a primitive per colour, unlit as in the viewer. */
    private int floor() {
        int n = node("floor");
        ObjectNode node = doc.nodeObject(n);
        node.set("translation", vector(new Vec3(0, clip.groundHeight(), 0)));
        ObjectNode mesh = doc.meshes.addObject().put("name", "floor");
        ArrayNode primitives = mesh.putArray("primitives");
        primitives.add(primitive(ShapeMeshes.checker(options.floorHalfSize(), options.floorTile(), true),
                material("floor light", options.colours().floorLight(), true)));
        primitives.add(primitive(ShapeMeshes.checker(options.floorHalfSize(), options.floorTile(), false),
                material("floor dark", options.colours().floorDark(), true)));
        node.put("mesh", doc.meshes.size() - 1);
        return n;
    }

    /** A perspective camera (it looks down its -z, y up) at the eye, turned to the target. */
    private int camera(ExportOptions.CameraView c) {
        return doc.camera(c);
    }

    // ---- animation ------------------------------------------------------------------------

    /** The sample times, shared by every channel's sampler. */
    private int timeAccessor() {
        List<MotionClip.Sample> samples = clip.samples();
        float[] t = new float[samples.size()];
        for (int i = 0; i < t.length; i++) {
            t[i] = (float) samples.get(i).time();
        }
        return doc.times(t);
    }

    /** Linear translation and rotation channels of node {@code n} from each sample's frame. */
    private void animate(int n, IntFunction<Frame> frame) {
        List<MotionClip.Sample> samples = clip.samples();
        float[] translation = new float[3 * samples.size()];
        float[] rotation = new float[4 * samples.size()];
        Quat previous = Quat.IDENTITY;
        for (int i = 0; i < samples.size(); i++) {
            Frame fr = frame.apply(i);
            put(translation, 3 * i, fr.origin());
            // the sign nearest the previous sample's, so that interpolation turns the short way
            Quat q = fr.rotation().normalized();
            q = q.dot(previous) < 0 ? new Quat(-q.w(), -q.x(), -q.y(), -q.z()) : q;
            previous = q;
            rotation[4 * i] = (float) q.x();
            rotation[4 * i + 1] = (float) q.y();
            rotation[4 * i + 2] = (float) q.z();
            rotation[4 * i + 3] = (float) q.w();
        }
        channel(n, "translation", "LINEAR", accessor(view(floats(translation), null), GltfDocument.FLOAT, samples.size(), "VEC3", null, null));
        channel(n, "rotation", "LINEAR", accessor(view(floats(rotation), null), GltfDocument.FLOAT, samples.size(), "VEC4", null, null));
    }

    /** A step-interpolated channel of node {@code n} (a scale of 0 hides it). */
    private void stepChannel(int n, String path, Function<MotionClip.Sample, Vec3> value) {
        List<MotionClip.Sample> samples = clip.samples();
        float[] v = new float[3 * samples.size()];
        for (int i = 0; i < samples.size(); i++) {
            put(v, 3 * i, value.apply(samples.get(i)));
        }
        channel(n, path, "STEP", accessor(view(floats(v), null), GltfDocument.FLOAT, samples.size(), "VEC3", null, null));
    }

    private void channel(int node, String path, String interpolation, int output) {
        doc.channel(node, path, interpolation, times, output);
    }

    // ---- meshes and materials -------------------------------------------------------------

    private int mesh(String name, TriangleMesh mesh, int material) {
        ObjectNode m = doc.meshes.addObject().put("name", name);
        m.putArray("primitives").add(primitive(mesh, material));
        return doc.meshes.size() - 1;
    }

    private ObjectNode primitive(TriangleMesh mesh, int material) {
        ObjectNode p = f.objectNode();
        int n = mesh.vertexCount();
        ObjectNode attributes = p.putObject("attributes");
        attributes.put("POSITION", accessor(view(floats(mesh.positions()), GltfDocument.ARRAY_BUFFER), GltfDocument.FLOAT, n, "VEC3", mesh.min(), mesh.max()));
        attributes.put("NORMAL", accessor(view(floats(mesh.normals()), GltfDocument.ARRAY_BUFFER), GltfDocument.FLOAT, n, "VEC3", null, null));
        p.put("indices", doc.indices(mesh.indices(), n));
        p.put("material", material);
        p.put("mode", 4); // triangles
        return p;
    }

    private int material(String name, float[] srgba, boolean unlit) {
        return doc.material(name, srgba, unlit);
    }

    private int node(String name) {
        return doc.node(name);
    }

    private void addChild(int parent, int child) {
        doc.addChild(parent, child);
    }

    private int accessor(int view, int componentType, int count, String type, float[] min, float[] max) {
        return doc.accessor(view, componentType, count, type, min, max);
    }

    private int view(byte[] data, Integer target) {
        return doc.view(data, target);
    }

    private static byte[] floats(float[] values) {
        return GltfDocument.floats(values);
    }

    private static void put(float[] out, int at, Vec3 v) {
        out[at] = (float) v.x();
        out[at + 1] = (float) v.y();
        out[at + 2] = (float) v.z();
    }

    private ArrayNode vector(Vec3 v) {
        return f.arrayNode().add((float) v.x()).add((float) v.y()).add((float) v.z());
    }

    private ArrayNode quaternion(Quat q) {
        return f.arrayNode().add(q.x()).add(q.y()).add(q.z()).add(q.w());
    }
}
