package handsim.export;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.math.Quat;
import handsim.math.Vec3;
import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A glTF 2.0 document being assembled: its nodes, meshes, materials, accessors and buffer views
 * over one binary buffer, and one animation's samplers and channels. The writers of a hand run
 * ({@link GltfWriter}) and of a card trial ({@link SurfaceGltf}) fill it; {@link #finish} makes
 * the JSON and the buffer, written as a .glb or a .gltf with its .bin.
 */
final class GltfDocument {

    /** glTF's codes: component types, buffer view targets. */
    static final int FLOAT = 5126, UNSIGNED_SHORT = 5123, UNSIGNED_INT = 5125, ARRAY_BUFFER = 34962,
            ELEMENT_ARRAY_BUFFER = 34963;
    static final String UNLIT = "KHR_materials_unlit";

    final JsonNodeFactory f = JsonNodeFactory.instance;
    final ObjectNode root = f.objectNode();
    final ArrayNode nodes = f.arrayNode();
    final ArrayNode meshes = f.arrayNode();
    private final ArrayNode materials = f.arrayNode();
    private final ArrayNode accessors = f.arrayNode();
    private final ArrayNode bufferViews = f.arrayNode();
    private final ArrayNode samplers = f.arrayNode();
    private final ArrayNode channels = f.arrayNode();
    private final ByteArrayOutputStream bin = new ByteArrayOutputStream();
    private final Map<String, Integer> materialIndex = new LinkedHashMap<>();
    private final double roughness;
    private boolean unlitUsed;

    /** A document whose materials have the surface finish {@code roughness}. */
    GltfDocument(double roughness) {
        this.roughness = roughness;
        root.putObject("asset").put("version", "2.0").put("generator", "handsim");
    }

    /** The JSON document and its binary buffer. */
    record Gltf(ObjectNode json, byte[] bin) {

        /** As one binary .glb: the header, the JSON chunk and the binary chunk. */
        byte[] glb() {
            byte[] text = padded(json.toString().getBytes(StandardCharsets.UTF_8), (byte) ' ');
            byte[] data = padded(bin, (byte) 0);
            int length = 12 + 8 + text.length + 8 + data.length;
            ByteBuffer out = ByteBuffer.allocate(length).order(ByteOrder.LITTLE_ENDIAN);
            out.putInt(0x46546C67).putInt(2).putInt(length); // "glTF", version 2
            out.putInt(text.length).putInt(0x4E4F534A).put(text); // "JSON"
            out.putInt(data.length).putInt(0x004E4942).put(data); // "BIN\0"
            return out.array();
        }

        /** As a .gltf document whose buffer is the file {@code binName} beside it. */
        byte[] gltf(String binName) {
            ObjectNode copy = json.deepCopy();
            ((ObjectNode) copy.withArray("buffers").get(0)).put("uri", binName);
            try {
                return new ObjectMapper().writerWithDefaultPrettyPrinter().writeValueAsBytes(copy);
            } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
                throw new IllegalStateException(e);
            }
        }

        private static byte[] padded(byte[] b, byte pad) {
            byte[] out = Arrays.copyOf(b, (b.length + 3) / 4 * 4);
            Arrays.fill(out, b.length, out.length, pad);
            return out;
        }
    }

    /** The scene of {@code sceneNodes} and the animation, both named {@code title}; the document is then complete. */
    Gltf finish(String title, List<Integer> sceneNodes) {
        root.put("scene", 0);
        ArrayNode scene = root.putArray("scenes").addObject().put("name", title).putArray("nodes");
        sceneNodes.forEach(scene::add);
        root.set("nodes", nodes);
        root.set("meshes", meshes);
        root.set("materials", materials);
        ObjectNode animation = root.putArray("animations").addObject();
        animation.put("name", title);
        animation.set("channels", channels);
        animation.set("samplers", samplers);
        root.set("accessors", accessors);
        root.set("bufferViews", bufferViews);
        root.putArray("buffers").addObject().put("byteLength", bin.size());
        if (unlitUsed) {
            root.putArray("extensionsUsed").add(UNLIT);
        }
        return new Gltf(root, bin.toByteArray());
    }

    /** Sample times (s) as the input accessor of the animation's samplers; they must increase. */
    int times(float[] t) {
        for (int i = 1; i < t.length; i++) {
            if (!(t[i] > t[i - 1])) {
                throw new IllegalArgumentException("sample times must increase (float seconds), got " + t[i - 1] + " then " + t[i]);
            }
        }
        return accessor(view(floats(t), null), FLOAT, t.length, "SCALAR", new float[] {t[0]}, new float[] {t[t.length - 1]});
    }

    /** An animation channel of node {@code node}'s {@code path}, its sampler from {@code input} times to {@code output} values. */
    void channel(int node, String path, String interpolation, int input, int output) {
        samplers.addObject().put("input", input).put("interpolation", interpolation).put("output", output);
        ObjectNode c = channels.addObject().put("sampler", samplers.size() - 1);
        c.putObject("target").put("node", node).put("path", path);
    }

    /**
     * The material {@code name} of the colour {@code srgba} (made once): non-metallic, blended when
     * translucent; {@code unlit} for what the viewer draws without light (the plane from both sides).
     */
    int material(String name, float[] srgba, boolean unlit) {
        return materialIndex.computeIfAbsent(name, k -> {
            ObjectNode m = materials.addObject().put("name", name);
            ArrayNode colour = m.putObject("pbrMetallicRoughness").put("metallicFactor", 0.0).put("roughnessFactor", roughness)
                    .putArray("baseColorFactor");
            for (int i = 0; i < 3; i++) {
                colour.add(linear(srgba[i]));
            }
            colour.add(srgba[3]);
            if (srgba[3] < 1) {
                m.put("alphaMode", "BLEND");
            }
            if (unlit) {
                m.putObject("extensions").putObject(UNLIT);
                unlitUsed = true;
                m.put("doubleSided", srgba[3] < 1);
            }
            return materials.size() - 1;
        });
    }

    /** A two-sided material (thin shells seen from either side). */
    int twoSidedMaterial(String name, float[] srgba) {
        int m = material(name, srgba, false);
        ((ObjectNode) materials.get(m)).put("doubleSided", true);
        return m;
    }

    /** sRGB's transfer function inverted (IEC 61966-2-1): the linear value glTF's colour factors hold. */
    static double linear(double c) {
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }

    /** A perspective camera node (it looks down its −z, y up) at the view's eye, turned to its target. */
    int camera(ExportOptions.CameraView c) {
        ObjectNode perspective = root.withArray("cameras").addObject().put("type", "perspective").putObject("perspective");
        perspective.put("yfov", c.fovY()).put("znear", c.near()).put("zfar", c.far());
        Vec3 forward = c.target().minus(c.eye()).normalized();
        Vec3 right = forward.cross(Vec3.Y).normalized();
        Vec3 up = right.cross(forward);
        int n = node("camera");
        nodeObject(n).put("camera", root.withArray("cameras").size() - 1);
        nodeObject(n).set("translation", f.arrayNode().add((float) c.eye().x()).add((float) c.eye().y()).add((float) c.eye().z()));
        Quat q = Quat.fromFrame(right, up, forward.negate());
        nodeObject(n).set("rotation", f.arrayNode().add(q.x()).add(q.y()).add(q.z()).add(q.w()));
        return n;
    }

    int node(String name) {
        nodes.addObject().put("name", name);
        return nodes.size() - 1;
    }

    ObjectNode nodeObject(int n) {
        return (ObjectNode) nodes.get(n);
    }

    void addChild(int parent, int child) {
        nodeObject(parent).withArray("children").add(child);
    }

    int accessor(int view, int componentType, int count, String type, float[] min, float[] max) {
        ObjectNode a = accessors.addObject().put("bufferView", view).put("componentType", componentType).put("count", count)
                .put("type", type);
        if (min != null) {
            ArrayNode lo = a.putArray("min"), hi = a.putArray("max");
            for (int i = 0; i < min.length; i++) {
                lo.add(min[i]);
                hi.add(max[i]);
            }
        }
        return accessors.size() - 1;
    }

    /** Appends {@code data} to the buffer, 4-byte aligned, as a buffer view for {@code target} (null: animation data). */
    int view(byte[] data, Integer target) {
        while (bin.size() % 4 != 0) {
            bin.write(0);
        }
        ObjectNode v = bufferViews.addObject().put("buffer", 0).put("byteOffset", bin.size()).put("byteLength", data.length);
        if (target != null) {
            v.put("target", target);
        }
        bin.write(data, 0, data.length);
        return bufferViews.size() - 1;
    }

    /** Triangle indices as an accessor: unsigned shorts when {@code vertices} fit, else unsigned ints. */
    int indices(int[] indices, int vertices) {
        boolean small = vertices <= 0xffff;
        ByteBuffer b = ByteBuffer.allocate(indices.length * (small ? 2 : 4)).order(ByteOrder.LITTLE_ENDIAN);
        for (int i : indices) {
            if (small) {
                b.putShort((short) i);
            } else {
                b.putInt(i);
            }
        }
        return accessor(view(b.array(), ELEMENT_ARRAY_BUFFER), small ? UNSIGNED_SHORT : UNSIGNED_INT, indices.length, "SCALAR", null, null);
    }

    static byte[] floats(float[] values) {
        ByteBuffer b = ByteBuffer.allocate(4 * values.length).order(ByteOrder.LITTLE_ENDIAN);
        for (float v : values) {
            b.putFloat(v);
        }
        return b.array();
    }
}
