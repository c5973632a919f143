package handsim.cards.mesh;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A triangle mesh: vertex positions (3 per vertex, metres) and triangles (3 vertex indices,
 * counter-clockwise seen from the front). Edges and hinges are derived once.
 */
public final class ShellMesh {

    private final double[] vertices;
    private final int[] triangles;
    private final int[] edges;
    private final int[] hinges;

    public ShellMesh(double[] vertices, int[] triangles) {
        this.vertices = vertices.clone();
        this.triangles = triangles.clone();
        // every directed edge a→b of a triangle, with the opposite vertex
        Map<Long, Integer> opposite = new HashMap<>();
        List<int[]> edgeList = new ArrayList<>();
        for (int t = 0; t < triangles.length / 3; t++) {
            for (int k = 0; k < 3; k++) {
                int a = triangles[3 * t + k];
                int b = triangles[3 * t + (k + 1) % 3];
                opposite.put(key(a, b), triangles[3 * t + (k + 2) % 3]);
            }
        }
        List<int[]> hingeList = new ArrayList<>();
        for (int t = 0; t < triangles.length / 3; t++) {
            for (int k = 0; k < 3; k++) {
                int a = triangles[3 * t + k];
                int b = triangles[3 * t + (k + 1) % 3];
                Integer other = opposite.get(key(b, a));
                if (other == null || a < b) {
                    edgeList.add(new int[] {Math.min(a, b), Math.max(a, b)});
                }
                if (other != null && a < b) {
                    // triangle (a, b, c) and triangle (b, a, d)
                    hingeList.add(new int[] {a, b, triangles[3 * t + (k + 2) % 3], other});
                }
            }
        }
        edges = edgeList.stream().flatMapToInt(java.util.Arrays::stream).toArray();
        hinges = hingeList.stream().flatMapToInt(java.util.Arrays::stream).toArray();
    }

    private static long key(int a, int b) {
        return ((long) a << 32) | (b & 0xffffffffL);
    }

    public int vertexCount() {
        return vertices.length / 3;
    }

    public int triangleCount() {
        return triangles.length / 3;
    }

    public double[] vertices() {
        return vertices.clone();
    }

    public int[] triangles() {
        return triangles.clone();
    }

    /** Each edge once: pairs of vertex indices. */
    public int[] edges() {
        return edges.clone();
    }

    /** Interior edges as hinges (x0, x1, x2, x3): triangles (x0, x1, x2) and (x1, x0, x3). */
    public int[] hinges() {
        return hinges.clone();
    }

    /** Number of edges on the boundary (in one triangle only). */
    public int boundaryEdgeCount() {
        return edges.length / 2 - hinges.length / 4;
    }
}
