package handsim.mesh;

import handsim.math.Vec3;
import java.util.Arrays;

/** Collects vertices and triangles into a {@link TriangleMesh}. */
final class MeshBuilder {

    private float[] positions = new float[3 * 64];
    private float[] normals = new float[3 * 64];
    private int[] indices = new int[3 * 64];
    private int vertices;
    private int corners;

    /** Adds a vertex at {@code p} with unit normal {@code n}; returns its index. */
    int vertex(Vec3 p, Vec3 n) {
        if (3 * vertices + 3 > positions.length) {
            positions = Arrays.copyOf(positions, 2 * positions.length);
            normals = Arrays.copyOf(normals, 2 * normals.length);
        }
        int o = 3 * vertices;
        positions[o] = (float) p.x();
        positions[o + 1] = (float) p.y();
        positions[o + 2] = (float) p.z();
        normals[o] = (float) n.x();
        normals[o + 1] = (float) n.y();
        normals[o + 2] = (float) n.z();
        return vertices++;
    }

    /** A triangle of vertices a, b, c, counter-clockwise seen from its front. */
    void triangle(int a, int b, int c) {
        if (corners + 3 > indices.length) {
            indices = Arrays.copyOf(indices, 2 * indices.length);
        }
        indices[corners++] = a;
        indices[corners++] = b;
        indices[corners++] = c;
    }

    /** The quad a, b, c, d (counter-clockwise seen from its front) as two triangles. */
    void quad(int a, int b, int c, int d) {
        triangle(a, b, c);
        triangle(a, c, d);
    }

    /** Appends {@code mesh}'s vertices and triangles. */
    void add(TriangleMesh mesh) {
        int base = vertices;
        for (int v = 0; v < mesh.vertexCount(); v++) {
            vertex(new Vec3(mesh.position(v, 0), mesh.position(v, 1), mesh.position(v, 2)),
                    new Vec3(mesh.normal(v, 0), mesh.normal(v, 1), mesh.normal(v, 2)));
        }
        for (int t = 0; t < mesh.triangleCount(); t++) {
            triangle(base + mesh.corner(t, 0), base + mesh.corner(t, 1), base + mesh.corner(t, 2));
        }
    }

    TriangleMesh build() {
        return new TriangleMesh(Arrays.copyOf(positions, 3 * vertices), Arrays.copyOf(normals, 3 * vertices),
                Arrays.copyOf(indices, corners));
    }
}
