package handsim.app;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A card's mid-surface drawn as the slab it is: the surface moved half the thickness out along
 * each vertex's normal (area-weighted) on either side, joined along the boundary by a band of
 * quads, so that a card seen from its edge is as thick as it is and a stack shows its layers.
 */
final class CardSlab {

    /** Positions (3 per vertex, metres) and counter-clockwise triangles. */
    record Mesh(double[] positions, int[] triangles) {
    }

    private CardSlab() {
    }

    /** The slab of a mid-surface ({@code p}, 3 per vertex; {@code tris} counter-clockwise seen from its normal side). */
    static Mesh of(double[] p, int[] tris, double thickness) {
        int n = p.length / 3;
        double[] normal = new double[3 * n];
        for (int t = 0; t < tris.length / 3; t++) {
            int a = 3 * tris[3 * t], b = 3 * tris[3 * t + 1], c = 3 * tris[3 * t + 2];
            double ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
            double vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
            double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
            for (int k : new int[] {a, b, c}) {
                normal[k] += nx;
                normal[k + 1] += ny;
                normal[k + 2] += nz;
            }
        }
        double[] out = new double[6 * n];
        for (int i = 0; i < n; i++) {
            double len = Math.sqrt(normal[3 * i] * normal[3 * i] + normal[3 * i + 1] * normal[3 * i + 1] + normal[3 * i + 2] * normal[3 * i + 2]);
            for (int d = 0; d < 3; d++) {
                double offset = len > 0 ? 0.5 * thickness * normal[3 * i + d] / len : 0;
                out[3 * i + d] = p[3 * i + d] + offset;
                out[3 * (n + i) + d] = p[3 * i + d] - offset;
            }
        }
        List<Integer> faces = new ArrayList<>();
        for (int t = 0; t < tris.length / 3; t++) {
            int a = tris[3 * t], b = tris[3 * t + 1], c = tris[3 * t + 2];
            faces.addAll(List.of(a, b, c, n + a, n + c, n + b));
        }
        // boundary edges: those of one triangle, kept in that triangle's direction
        Map<Long, int[]> edges = new HashMap<>();
        for (int t = 0; t < tris.length / 3; t++) {
            for (int k = 0; k < 3; k++) {
                int a = tris[3 * t + k], b = tris[3 * t + (k + 1) % 3];
                long key = ((long) Math.min(a, b) << 32) | Math.max(a, b);
                if (edges.remove(key) == null) {
                    edges.put(key, new int[] {a, b});
                }
            }
        }
        edges.values().stream().sorted((x, y) -> x[0] != y[0] ? Integer.compare(x[0], y[0]) : Integer.compare(x[1], y[1])).forEach(e -> {
            int a = e[0], b = e[1];
            faces.addAll(List.of(b, a, n + a, b, n + a, n + b));
        });
        return new Mesh(out, faces.stream().mapToInt(Integer::intValue).toArray());
    }
}
