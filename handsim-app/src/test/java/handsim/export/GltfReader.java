package handsim.export;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import handsim.kin.Frame;
import handsim.math.Quat;
import handsim.math.Vec3;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;

/**
 * A small glTF 2.0 reader for tests, written from the specification, not from the writer: reads
 * a .glb (header, JSON chunk, BIN chunk) or a .gltf with its buffer file, float accessors, the
 * node tree and the first animation's channels, and gives a node's world transform at a
 * keyframe (translation and rotation; scale is not composed: the arm's nodes have none).
 */
final class GltfReader {

    final JsonNode json;
    private final ByteBuffer bin;
    private final Map<Integer, Integer> parent = new HashMap<>();
    /** Node, then "translation" / "rotation" / "scale": the sampler's output accessor. */
    private final Map<Integer, Map<String, Integer>> channels = new HashMap<>();
    /** Node, then path: the sampler's input accessor. */
    private final Map<Integer, Map<String, Integer>> inputs = new HashMap<>();

    private GltfReader(JsonNode json, ByteBuffer bin) {
        this.json = json;
        this.bin = bin.order(ByteOrder.LITTLE_ENDIAN);
        JsonNode nodes = json.get("nodes");
        for (int n = 0; n < nodes.size(); n++) {
            if (nodes.get(n).has("children")) {
                for (JsonNode c : nodes.get(n).get("children")) {
                    parent.put(c.asInt(), n);
                }
            }
        }
        JsonNode animation = json.get("animations").get(0);
        for (JsonNode c : animation.get("channels")) {
            JsonNode sampler = animation.get("samplers").get(c.get("sampler").asInt());
            int node = c.get("target").get("node").asInt();
            String path = c.get("target").get("path").asText();
            channels.computeIfAbsent(node, k -> new HashMap<>()).put(path, sampler.get("output").asInt());
            inputs.computeIfAbsent(node, k -> new HashMap<>()).put(path, sampler.get("input").asInt());
        }
    }

    static GltfReader read(Path file) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        ObjectMapper mapper = new ObjectMapper();
        if (file.toString().endsWith(".glb")) {
            ByteBuffer b = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
            if (b.getInt(0) != 0x46546C67 || b.getInt(4) != 2 || b.getInt(8) != bytes.length) {
                throw new IOException("not a glTF 2.0 binary of the file's length");
            }
            int jsonLength = b.getInt(12);
            if (b.getInt(16) != 0x4E4F534A) {
                throw new IOException("the first chunk is not JSON");
            }
            JsonNode json = mapper.readTree(new String(bytes, 20, jsonLength, StandardCharsets.UTF_8));
            int at = 20 + jsonLength;
            int binLength = b.getInt(at);
            if (b.getInt(at + 4) != 0x004E4942) {
                throw new IOException("the second chunk is not BIN");
            }
            return new GltfReader(json, ByteBuffer.wrap(bytes, at + 8, binLength).slice());
        }
        JsonNode json = mapper.readTree(bytes);
        String uri = json.get("buffers").get(0).get("uri").asText();
        return new GltfReader(json, ByteBuffer.wrap(Files.readAllBytes(file.resolveSibling(uri))));
    }

    int node(String name) {
        JsonNode nodes = json.get("nodes");
        for (int n = 0; n < nodes.size(); n++) {
            if (name.equals(nodes.get(n).path("name").asText())) {
                return n;
            }
        }
        throw new IllegalArgumentException("no node named " + name);
    }

    String name(int node) {
        return json.get("nodes").get(node).path("name").asText();
    }

    /** The parent node, or -1 for a scene root. */
    int parent(int node) {
        return parent.getOrDefault(node, -1);
    }

    boolean animates(int node, String path) {
        return channels.getOrDefault(node, Map.of()).containsKey(path);
    }

    /** The output accessor of a node's channel. */
    int output(int node, String path) {
        return channels.get(node).get(path);
    }

    /** The keyframe times of a node's channel. */
    float[] times(int node, String path) {
        return floats(inputs.get(node).get(path));
    }

    /** An accessor of floats, all its components in order (tightly packed, as this reader expects). */
    float[] floats(int accessor) {
        JsonNode a = json.get("accessors").get(accessor);
        if (a.get("componentType").asInt() != 5126) {
            throw new IllegalArgumentException("accessor " + accessor + " is not of floats");
        }
        int width = switch (a.get("type").asText()) {
            case "SCALAR" -> 1;
            case "VEC3" -> 3;
            case "VEC4" -> 4;
            default -> throw new IllegalArgumentException(a.get("type").asText());
        };
        JsonNode view = json.get("bufferViews").get(a.get("bufferView").asInt());
        int offset = view.path("byteOffset").asInt(0) + a.path("byteOffset").asInt(0);
        float[] out = new float[width * a.get("count").asInt()];
        for (int i = 0; i < out.length; i++) {
            out[i] = bin.getFloat(offset + 4 * i);
        }
        return out;
    }

    /** A node's local transform at keyframe {@code key}: the animated value, or the node's own. */
    Frame local(int node, int key) {
        JsonNode n = json.get("nodes").get(node);
        Vec3 t = Vec3.ZERO;
        Quat r = Quat.IDENTITY;
        if (animates(node, "translation")) {
            float[] v = floats(channels.get(node).get("translation"));
            t = new Vec3(v[3 * key], v[3 * key + 1], v[3 * key + 2]);
        } else if (n.has("translation")) {
            JsonNode v = n.get("translation");
            t = new Vec3(v.get(0).asDouble(), v.get(1).asDouble(), v.get(2).asDouble());
        }
        if (animates(node, "rotation")) {
            float[] v = floats(channels.get(node).get("rotation"));
            // glTF stores x, y, z, w
            r = new Quat(v[4 * key + 3], v[4 * key], v[4 * key + 1], v[4 * key + 2]).normalized();
        } else if (n.has("rotation")) {
            JsonNode v = n.get("rotation");
            r = new Quat(v.get(3).asDouble(), v.get(0).asDouble(), v.get(1).asDouble(), v.get(2).asDouble()).normalized();
        }
        return new Frame(t, r);
    }

    /** A node's world transform at keyframe {@code key}: its ancestors' local transforms composed from the root down. */
    Frame world(int node, int key) {
        int p = parent(node);
        return p < 0 ? local(node, key) : world(p, key).compose(local(node, key));
    }
}
