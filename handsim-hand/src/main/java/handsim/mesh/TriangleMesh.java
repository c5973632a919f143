package handsim.mesh;

import java.util.Arrays;

/**
 * Triangles with a normal per vertex: {@code positions} and {@code normals} hold x, y, z per
 * vertex (metres, unit normals), {@code indices} three vertex indices per triangle, counter-clockwise
 * seen from the side the normals point to. Immutable: the accessors hand out copies.
 */
public final class TriangleMesh {

    private final float[] positions;
    private final float[] normals;
    private final int[] indices;

    TriangleMesh(float[] positions, float[] normals, int[] indices) {
        if (positions.length != normals.length || positions.length % 3 != 0 || indices.length % 3 != 0) {
            throw new IllegalArgumentException("a mesh needs x, y, z per vertex and three indices per triangle");
        }
        this.positions = positions;
        this.normals = normals;
        this.indices = indices;
    }

    public int vertexCount() {
        return positions.length / 3;
    }

    public int triangleCount() {
        return indices.length / 3;
    }

    public float[] positions() {
        return positions.clone();
    }

    public float[] normals() {
        return normals.clone();
    }

    public int[] indices() {
        return indices.clone();
    }

    /** Coordinate {@code axis} (0 x, 1 y, 2 z) of vertex {@code v}. */
    public float position(int v, int axis) {
        return positions[3 * v + axis];
    }

    public float normal(int v, int axis) {
        return normals[3 * v + axis];
    }

    /** Vertex {@code corner} (0-2) of triangle {@code t}. */
    public int corner(int t, int corner) {
        return indices[3 * t + corner];
    }

    /** Smallest x, y, z over the vertices. */
    public float[] min() {
        return bound(-1);
    }

    /** Largest x, y, z over the vertices. */
    public float[] max() {
        return bound(1);
    }

    private float[] bound(int sign) {
        float[] b = new float[3];
        Arrays.fill(b, sign > 0 ? Float.NEGATIVE_INFINITY : Float.POSITIVE_INFINITY);
        for (int i = 0; i < positions.length; i++) {
            b[i % 3] = sign > 0 ? Math.max(b[i % 3], positions[i]) : Math.min(b[i % 3], positions[i]);
        }
        return b;
    }
}
