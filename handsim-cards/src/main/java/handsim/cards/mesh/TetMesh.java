package handsim.cards.mesh;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A tetrahedral mesh: vertex positions (metres), tetrahedra (4 vertex indices, positive volume),
 * the boundary surface (triangles oriented outwards) and which vertices are "bone": inner nodes
 * that bone control moves as Dirichlet conditions (thesis 3.2.3).
 */
public final class TetMesh {

    private final double[] vertices;
    private final int[] tets;
    private final int[] surface;
    private final boolean[] bone;

    public TetMesh(double[] vertices, int[] tets, boolean[] bone) {
        this.vertices = vertices.clone();
        this.tets = tets.clone();
        this.bone = bone.clone();
        this.surface = boundary(tets);
    }

    /** Faces that belong to one tetrahedron only, oriented with the outward normal. */
    private static int[] boundary(int[] tets) {
        // faces of tet (a, b, c, d) with outward orientation when the tet has positive volume
        int[][] faces = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
        Map<String, int[]> seen = new HashMap<>();
        Map<String, Integer> count = new HashMap<>();
        List<String> order = new ArrayList<>();
        for (int t = 0; t < tets.length / 4; t++) {
            for (int[] f : faces) {
                int[] tri = {tets[4 * t + f[0]], tets[4 * t + f[1]], tets[4 * t + f[2]]};
                int[] sorted = tri.clone();
                java.util.Arrays.sort(sorted);
                String key = sorted[0] + ":" + sorted[1] + ":" + sorted[2];
                if (count.merge(key, 1, Integer::sum) == 1) {
                    seen.put(key, tri);
                    order.add(key);
                }
            }
        }
        return order.stream().filter(k -> count.get(k) == 1).flatMapToInt(k -> java.util.Arrays.stream(seen.get(k))).toArray();
    }

    public int vertexCount() {
        return vertices.length / 3;
    }

    public int tetCount() {
        return tets.length / 4;
    }

    public double[] vertices() {
        return vertices.clone();
    }

    public int[] tets() {
        return tets.clone();
    }

    /** Boundary triangles, outward. */
    public int[] surface() {
        return surface.clone();
    }

    public boolean isBone(int vertex) {
        return bone[vertex];
    }

    public int boneCount() {
        int n = 0;
        for (boolean b : bone) {
            n += b ? 1 : 0;
        }
        return n;
    }
}
