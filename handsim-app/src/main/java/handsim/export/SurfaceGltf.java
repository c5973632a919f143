package handsim.export;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Deforming surfaces (a card trial's cards and fingertips) as glTF 2.0 with vertex animation by
 * morph targets, which the Khronos validator, three.js and Blender's importer (as shape keys)
 * all read: each surface that moves is a mesh whose base is its first frame and whose targets
 * are its later frames' displacements of positions and normals; one weights channel per mesh,
 * linearly interpolated, gives target k the weight 1 at frame k's time and 0 at the others, so
 * the mesh passes through every recorded frame. A surface that never moves is a plain mesh.
 * Metres, y up; colours sRGB as the viewer's, two-sided (thin shells).
 */
public final class SurfaceGltf {

    /** A surface: its name, colour (sRGB + alpha), triangles and positions per frame (3 per vertex, y up). */
    public record Surface(String name, float[] srgba, int[] triangles, List<float[]> frames) {
    }

    private SurfaceGltf() {
    }

    /** The files that {@code target} (.glb, or .gltf with its .bin) holds for these surfaces, in the order to write them. */
    public static List<ExportTarget.FileContent> files(ExportTarget target, String title, float[] times, List<Surface> surfaces,
                                                       double roughness, ExportOptions.CameraView camera) {
        if (target.format() != ExportTarget.Format.GLTF) {
            throw new IllegalArgumentException("a card trial is written as glTF (.glb or .gltf), not " + target.format().lower());
        }
        if (times.length < 2) {
            throw new IllegalArgumentException("an animation needs at least two frames, got " + times.length);
        }
        return target.gltfFiles(build(title, times, surfaces, roughness, camera));
    }

    /** The document; with a camera node at {@code camera} when not null. */
    static GltfDocument.Gltf build(String title, float[] times, List<Surface> surfaces, double roughness, ExportOptions.CameraView camera) {
        GltfDocument doc = new GltfDocument(roughness);
        int input = doc.times(times);
        List<Integer> scene = new ArrayList<>();
        for (Surface s : surfaces) {
            if (s.frames().size() != times.length) {
                throw new IllegalArgumentException(s.name() + ": " + s.frames().size() + " frames for " + times.length + " times");
            }
            int n = doc.node(s.name());
            doc.nodeObject(n).put("mesh", mesh(doc, s, input));
            scene.add(n);
        }
        if (camera != null) {
            scene.add(doc.camera(camera));
        }
        return doc.finish(title, scene);
    }

    private static int mesh(GltfDocument doc, Surface s, int input) {
        float[] base = s.frames().get(0);
        float[] baseNormals = normals(base, s.triangles());
        ObjectNode p = doc.f.objectNode();
        ObjectNode attributes = p.putObject("attributes");
        attributes.put("POSITION", positions(doc, base, GltfDocument.ARRAY_BUFFER));
        attributes.put("NORMAL", doc.accessor(doc.view(GltfDocument.floats(baseNormals), GltfDocument.ARRAY_BUFFER), GltfDocument.FLOAT,
                base.length / 3, "VEC3", null, null));
        p.put("indices", doc.indices(s.triangles(), base.length / 3));
        p.put("material", doc.twoSidedMaterial(s.name(), s.srgba()));
        p.put("mode", 4);
        ObjectNode mesh = doc.meshes.addObject().put("name", s.name());
        mesh.putArray("primitives").add(p);
        int meshIndex = doc.meshes.size() - 1;
        boolean moves = s.frames().stream().anyMatch(f -> !Arrays.equals(f, base));
        if (!moves) {
            return meshIndex;
        }
        int k = s.frames().size() - 1;
        ArrayNode targets = p.putArray("targets");
        ArrayNode weights = mesh.putArray("weights");
        for (int t = 1; t <= k; t++) {
            float[] frame = s.frames().get(t);
            float[] dp = new float[base.length], dn = new float[base.length];
            float[] fn = normals(frame, s.triangles());
            for (int i = 0; i < base.length; i++) {
                dp[i] = frame[i] - base[i];
                dn[i] = fn[i] - baseNormals[i];
            }
            ObjectNode target = targets.addObject();
            target.put("POSITION", positions(doc, dp, null));
            target.put("NORMAL", doc.accessor(doc.view(GltfDocument.floats(dn), null), GltfDocument.FLOAT, base.length / 3, "VEC3", null, null));
            weights.add(0.0);
        }
        // frame i: target i at weight 1, the rest 0 (frame 0: all 0), interpolated linearly between frames
        float[] w = new float[(k + 1) * k];
        for (int i = 1; i <= k; i++) {
            w[i * k + (i - 1)] = 1;
        }
        int n = doc.nodes.size() - 1;
        doc.channel(n, "weights", "LINEAR", input, doc.accessor(doc.view(GltfDocument.floats(w), null), GltfDocument.FLOAT, w.length, "SCALAR", null, null));
        return meshIndex;
    }

    /** A VEC3 accessor of positions with the min and max glTF requires of them. */
    private static int positions(GltfDocument doc, float[] p, Integer target) {
        float[] min = {Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE}, max = {-Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE};
        for (int i = 0; i < p.length; i++) {
            min[i % 3] = Math.min(min[i % 3], p[i]);
            max[i % 3] = Math.max(max[i % 3], p[i]);
        }
        return doc.accessor(doc.view(GltfDocument.floats(p), target), GltfDocument.FLOAT, p.length / 3, "VEC3", min, max);
    }

    /** Unit vertex normals, area-weighted over the triangles (a vertex on none gets +y). */
    static float[] normals(float[] p, int[] tris) {
        double[] n = new double[p.length];
        for (int t = 0; t < tris.length / 3; t++) {
            int a = 3 * tris[3 * t], b = 3 * tris[3 * t + 1], c = 3 * tris[3 * t + 2];
            double ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
            double vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
            double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
            for (int v : new int[] {a, b, c}) {
                n[v] += nx;
                n[v + 1] += ny;
                n[v + 2] += nz;
            }
        }
        float[] out = new float[p.length];
        for (int i = 0; i < p.length / 3; i++) {
            double len = Math.sqrt(n[3 * i] * n[3 * i] + n[3 * i + 1] * n[3 * i + 1] + n[3 * i + 2] * n[3 * i + 2]);
            if (len > 0) {
                for (int d = 0; d < 3; d++) {
                    out[3 * i + d] = (float) (n[3 * i + d] / len);
                }
            } else {
                out[3 * i + 1] = 1;
            }
        }
        return out;
    }
}
