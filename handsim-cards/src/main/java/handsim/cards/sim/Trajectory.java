package handsim.cards.sim;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.report.Outputs;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;

/**
 * Recorded frames of a card scene for playback and rendering: for every body its surface nodes
 * (card vertices, fingertip skin) and triangles over them, and per frame the time and those
 * nodes' positions (metres, world frame, z up). Written as JSON.
 */
public final class Trajectory {

    /** A body's drawable surface: its kind, triangles over {@code nodes} (indices into it), a card's thickness (m; 0 for a fingertip). */
    public record Surface(String name, SoftBody.Kind kind, int[] nodes, int[] triangles, double thickness) {
    }

    /** One frame: time (s) and, per surface, its nodes' positions (3 per node). */
    public record Frame(double time, List<double[]> positions) {
    }

    private final List<Surface> surfaces;
    private final List<Frame> frames = new ArrayList<>();

    private Trajectory(List<Surface> surfaces) {
        this.surfaces = List.copyOf(surfaces);
    }

    /** An empty recording of the surfaces of {@code world}'s bodies. */
    public static Trajectory of(SoftWorld world) {
        List<Surface> out = new ArrayList<>();
        for (SoftBody b : world.bodies()) {
            int[] tri = b.surface();
            int[] nodes = new TreeSet<Integer>(java.util.Arrays.stream(tri).boxed().toList()).stream().mapToInt(Integer::intValue).toArray();
            int[] local = new int[tri.length];
            for (int i = 0; i < tri.length; i++) {
                local[i] = java.util.Arrays.binarySearch(nodes, tri[i]);
            }
            out.add(new Surface(b.name(), b.kind(), nodes, local, b.thickness()));
        }
        return new Trajectory(out);
    }

    /** Appends the state as a frame. */
    public void record(SimState state) {
        List<double[]> positions = new ArrayList<>();
        for (Surface s : surfaces) {
            double[] p = new double[3 * s.nodes().length];
            for (int i = 0; i < s.nodes().length; i++) {
                System.arraycopy(state.x, 3 * s.nodes()[i], p, 3 * i, 3);
            }
            positions.add(p);
        }
        frames.add(new Frame(state.time, positions));
    }

    public List<Surface> surfaces() {
        return surfaces;
    }

    public List<Frame> frames() {
        return List.copyOf(frames);
    }

    /** Writes the JSON file atomically ({@link Outputs}). */
    public void write(Path file) throws IOException {
        ObjectNode root = Json.mapper().createObjectNode();
        ArrayNode ss = root.putArray("surfaces");
        for (Surface s : surfaces) {
            ObjectNode o = ss.addObject();
            o.put("name", s.name());
            o.put("kind", s.kind().name());
            o.put("thickness", s.thickness());
            ArrayNode nodes = o.putArray("nodes");
            for (int n : s.nodes()) {
                nodes.add(n);
            }
            ArrayNode tris = o.putArray("triangles");
            for (int t : s.triangles()) {
                tris.add(t);
            }
        }
        ArrayNode fs = root.putArray("frames");
        for (Frame f : frames) {
            ObjectNode o = fs.addObject();
            o.put("time", f.time());
            ArrayNode ps = o.putArray("positions");
            for (double[] p : f.positions()) {
                ArrayNode a = ps.addArray();
                for (double v : p) {
                    a.add((float) v);
                }
            }
        }
        Outputs.write(file, out -> Json.mapper().writeValue(out, root));
    }

    /** Reads a file written by {@link #write}. */
    public static Trajectory read(Path file) {
        Json root = Json.load(file);
        List<Surface> surfaces = new ArrayList<>();
        for (Json s : root.array("surfaces")) {
            surfaces.add(new Surface(s.string("name"), SoftBody.Kind.valueOf(s.string("kind")),
                    ints(s.get("nodes").node()), ints(s.get("triangles").node()), s.number("thickness", 0)));
        }
        Trajectory t = new Trajectory(surfaces);
        for (Json f : root.array("frames")) {
            List<double[]> positions = new ArrayList<>();
            for (JsonNode p : f.get("positions").node()) {
                double[] v = new double[p.size()];
                for (int i = 0; i < v.length; i++) {
                    v[i] = p.get(i).asDouble();
                }
                positions.add(v);
            }
            t.frames.add(new Frame(f.number("time"), positions));
        }
        return t;
    }

    private static int[] ints(JsonNode a) {
        int[] out = new int[a.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = a.get(i).asInt();
        }
        return out;
    }
}
