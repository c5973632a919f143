package handsim.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.Shape;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The shapes' triangles face outward: each closed mesh is watertight with every edge shared by
 * two triangles turning opposite ways, every triangle's counter-clockwise normal points away
 * from the solid, and the enclosed volume (divergence theorem) is positive and near the shape's.
 */
@Tag("fast")
class ShapeMeshesTest {

    /** Shapes placed off the origin and tilted, so no axis-aligned luck hides a mistake. */
    static final List<Shape> SHAPES = List.of(
            new Shape.Capsule(new Vec3(0.01, -0.02, 0.03), new Vec3(0.05, 0.08, -0.02), 0.02),
            new Shape.Cylinder(new Vec3(-0.01, 0.02, 0.0), new Vec3(0.03, -0.06, 0.04), 0.03),
            new Shape.Box(new Vec3(0.02, -0.01, 0.03), new Vec3(0.08, 0.05, 0.02), Quat.fromAxisAngle(new Vec3(1, 2, 3).normalized(), 0.7)),
            new Shape.Sphere(new Vec3(-0.03, 0.01, 0.02), 0.04),
            new Shape.Capsule(new Vec3(0, 0, 0), new Vec3(0, -0.03, 0), 0.008));

    @Test
    void everyShapeIsAClosedSurfaceFacingOutward() {
        for (Detail detail : Detail.values()) {
            for (Shape shape : SHAPES) {
                TriangleMesh m = ShapeMeshes.of(shape, detail);
                String what = shape + " at " + detail;
                assertClosedAndConsistent(m, what);
                for (int t = 0; t < m.triangleCount(); t++) {
                    Vec3 a = vertex(m, m.corner(t, 0)), b = vertex(m, m.corner(t, 1)), c = vertex(m, m.corner(t, 2));
                    Vec3 faceNormal = b.minus(a).cross(c.minus(a));
                    assertTrue(faceNormal.norm() > 1e-12, "no degenerate triangle in " + what);
                    Vec3 centroid = a.plus(b).plus(c).times(1.0 / 3);
                    Vec3 outward = centroid.minus(core(shape, centroid));
                    assertTrue(faceNormal.dot(outward) > 0, "triangle " + t + " of " + what + " faces inward");
                    for (int k = 0; k < 3; k++) {
                        int v = m.corner(t, k);
                        Vec3 n = new Vec3(m.normal(v, 0), m.normal(v, 1), m.normal(v, 2));
                        assertEquals(1, n.norm(), 1e-6, "unit normals");
                        assertTrue(n.dot(faceNormal) > 0, "vertex normal agrees with the winding in " + what);
                    }
                }
                // inscribed polygons lose at most 1 - (n / 2 pi) sin(2 pi / n) of a round section:
                // 1.6 % at 20 slices, 6.5 % at 10 (and as much again for the latitude bands)
                double volume = volume(m);
                assertEquals(shape.volume(), volume, 0.14 * shape.volume(), "enclosed volume of " + what);
            }
        }
    }

    @Test
    void fineDetailCutsFingerSizedShapesAsSmall() {
        Shape finger = SHAPES.get(4);
        assertEquals(ShapeMeshes.of(finger, Detail.SMALL).triangleCount(), ShapeMeshes.of(finger, Detail.FINE).triangleCount());
        Shape arm = SHAPES.get(0);
        assertTrue(ShapeMeshes.of(arm, Detail.FINE).triangleCount() > ShapeMeshes.of(arm, Detail.SMALL).triangleCount());
    }

    @Test
    void theFloorsTwoColoursTileTheSquareAndFaceUp() {
        double half = 1.0, tile = 0.25;
        TriangleMesh light = ShapeMeshes.checker(half, tile, true), dark = ShapeMeshes.checker(half, tile, false);
        // (2 half / tile)^2 = 64 tiles, half of each colour, two triangles a tile
        assertEquals(64, light.triangleCount());
        assertEquals(64, dark.triangleCount());
        for (TriangleMesh m : List.of(light, dark, ShapeMeshes.square(0.3))) {
            for (int t = 0; t < m.triangleCount(); t++) {
                Vec3 a = vertex(m, m.corner(t, 0)), b = vertex(m, m.corner(t, 1)), c = vertex(m, m.corner(t, 2));
                assertTrue(b.minus(a).cross(c.minus(a)).y() > 0, "faces up, counter-clockwise seen from above");
            }
        }
    }

    /**
     * The nearest point of the shape's core to {@code p}: the direction from it to the surface is
     * outward. The core of a capsule or cylinder is the middle 80 % of its segment (a cap's
     * points then lie beyond its end).
     */
    private static Vec3 core(Shape s, Vec3 p) {
        if (s instanceof Shape.Capsule c) {
            return nearestOnSegment(c.a(), c.b(), p);
        } else if (s instanceof Shape.Cylinder c) {
            return nearestOnSegment(c.a(), c.b(), p);
        } else if (s instanceof Shape.Sphere sp) {
            return sp.center();
        }
        return ((Shape.Box) s).center();
    }

    private static Vec3 nearestOnSegment(Vec3 a, Vec3 b, Vec3 p) {
        Vec3 d = b.minus(a);
        double u = Math.max(0.1, Math.min(0.9, p.minus(a).dot(d) / d.normSquared()));
        return a.plus(d.times(u));
    }

    private static Vec3 vertex(TriangleMesh m, int v) {
        return new Vec3(m.position(v, 0), m.position(v, 1), m.position(v, 2));
    }

    /** Signed volume by the divergence theorem: positive when the triangles face outward. */
    private static double volume(TriangleMesh m) {
        double v = 0;
        for (int t = 0; t < m.triangleCount(); t++) {
            Vec3 a = vertex(m, m.corner(t, 0)), b = vertex(m, m.corner(t, 1)), c = vertex(m, m.corner(t, 2));
            v += a.dot(b.cross(c)) / 6;
        }
        return v;
    }

    /** Every directed edge (between vertex positions) is matched by the same edge the other way. */
    private static void assertClosedAndConsistent(TriangleMesh m, String what) {
        Map<String, Integer> edges = new HashMap<>();
        for (int t = 0; t < m.triangleCount(); t++) {
            for (int k = 0; k < 3; k++) {
                String from = key(m, m.corner(t, k)), to = key(m, m.corner(t, (k + 1) % 3));
                edges.merge(from + ">" + to, 1, Integer::sum);
            }
        }
        edges.forEach((edge, count) -> {
            String[] ends = edge.split(">");
            assertEquals(count, edges.getOrDefault(ends[1] + ">" + ends[0], 0), "edge " + edge + " of " + what
                    + " is met by as many triangles turning the other way (closed, consistently wound)");
        });
    }

    /** A vertex's position to 10 micrometres (seams computed two ways agree far closer). */
    private static String key(TriangleMesh m, int v) {
        return Math.round(m.position(v, 0) * 1e5) + "," + Math.round(m.position(v, 1) * 1e5) + "," + Math.round(m.position(v, 2) * 1e5);
    }
}
