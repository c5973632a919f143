package handsim.cards.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The generated card and fingertip meshes: counts from the thesis, orientation, closedness. */
@Tag("fast")
class MeshTest {

    private static final double W = 0.0889;
    private static final double H = 0.0635;

    @Test
    void cardCountsFollowTheGridArithmetic() {
        // sharp: (nx+1)(ny+1) vertices, 2 nx ny triangles; a rounded corner adds 3 of each
        ShellMesh sharp = CardMesher.generate(W, H, 11, 6, new boolean[4]);
        assertEquals(84, sharp.vertexCount());
        assertEquals(132, sharp.triangleCount());
        ShellMesh four = CardMesher.generate(W, H, 11, 6, new boolean[] {true, true, true, true});
        assertEquals(96, four.vertexCount());
        assertEquals(144, four.triangleCount());
        // the thesis' Fig. 3.6 counts, 93 / 141: an odd triangle count cannot come from four equal corners
        ShellMesh three = CardMesher.generate(W, H, 11, 6, new boolean[] {true, true, true, false});
        assertEquals(93, three.vertexCount());
        assertEquals(141, three.triangleCount());
    }

    @Test
    void cardTrianglesFaceUpAndTileTheCard() {
        for (boolean[] rounded : new boolean[][] {new boolean[4], {true, true, true, true}}) {
            ShellMesh m = CardMesher.generate(W, H, 11, 6, rounded);
            double[] v = m.vertices();
            int[] t = m.triangles();
            double area = 0;
            for (int k = 0; k < m.triangleCount(); k++) {
                double ax = v[3 * t[3 * k + 1]] - v[3 * t[3 * k]];
                double ay = v[3 * t[3 * k + 1] + 1] - v[3 * t[3 * k] + 1];
                double bx = v[3 * t[3 * k + 2]] - v[3 * t[3 * k]];
                double by = v[3 * t[3 * k + 2] + 1] - v[3 * t[3 * k] + 1];
                double a = 0.5 * (ax * by - ay * bx);
                assertTrue(a > 0, "triangle " + k + " faces +z");
                area += a;
            }
            // sharp: the full rectangle; rounded: each corner cell keeps the fan of five triangles
            // inscribed in a quarter ellipse, 5 · ½ sin(π/10) of the cell (an affine image of a
            // regular fan)
            double cell = W / 11 * H / 6;
            double expected = W * H - (rounded[0] ? 4 * (1 - 2.5 * Math.sin(Math.PI / 10)) * cell : 0);
            assertEquals(expected, area, 1e-12);
            // a disk: V − E + F = 1
            assertEquals(1, m.vertexCount() - m.edges().length / 2 + m.triangleCount());
        }
    }

    @Test
    void fingertipTetsArePositiveAndTheSkinIsClosed() {
        TetMesh tip = FingertipMesher.generate(0.012, 0.0075, 0.006, 11, 7, 7, 2);
        assertEquals(11 * 7 * 7, tip.vertexCount());
        assertEquals(6 * 10 * 6 * 6, tip.tetCount());
        assertEquals(7 * 3 * 3, tip.boneCount());
        double[] v = tip.vertices();
        int[] tets = tip.tets();
        double total = 0;
        double minVolume = Double.MAX_VALUE;
        for (int t = 0; t < tip.tetCount(); t++) {
            double vol = FingertipMesher.signedVolume(v, new int[] {tets[4 * t], tets[4 * t + 1], tets[4 * t + 2], tets[4 * t + 3]});
            assertTrue(vol > 0, "tet " + t + " has positive volume");
            total += vol;
            minVolume = Math.min(minVolume, vol);
        }
        // the mapped grid fills the ellipsoid up to its polyhedral skin: volume 4/3 π a b c within 10 %
        double ellipsoid = 4.0 / 3 * Math.PI * 0.012 * 0.0075 * 0.006;
        assertEquals(ellipsoid, total, 0.1 * ellipsoid);
        // no sliver: the smallest tet keeps at least 5 % of the mean volume
        assertTrue(minVolume > 0.05 * total / tip.tetCount(), "min volume " + minVolume);
        // a closed skin: every surface edge in exactly two surface triangles
        int[] s = tip.surface();
        Map<Long, Integer> edges = new HashMap<>();
        for (int k = 0; k < s.length / 3; k++) {
            for (int e = 0; e < 3; e++) {
                int a = s[3 * k + e];
                int b = s[3 * k + (e + 1) % 3];
                edges.merge(((long) Math.min(a, b) << 32) | Math.max(a, b), 1, Integer::sum);
            }
        }
        assertTrue(edges.values().stream().allMatch(c -> c == 2));
        // Euler characteristic of a sphere: V − E + F = 2
        long sv = java.util.Arrays.stream(s).distinct().count();
        assertEquals(2, sv - edges.size() + s.length / 3);
    }
}
