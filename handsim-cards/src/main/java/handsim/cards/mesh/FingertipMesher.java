package handsim.cards.mesh;

/**
 * A fingertip: an ellipsoid with semi-axes (a, b, c) filled with tetrahedra. A grid of
 * nx x ny x nz points on the cube [−1, 1]³ is mapped to the unit ball by the smooth cube-to-sphere
 * map x' = x √(1 − y²/2 − z²/2 + y²z²/3) (and cyclic), then scaled to the ellipsoid. Each grid
 * cell splits into six tetrahedra around its diagonal (Kuhn), mirrored in each octant so the
 * diagonal always runs from the cell's inner corner outwards: no tetrahedron then has all four
 * vertices on the surface, which keeps flat slivers out of the skin. Counts must be odd so the
 * mirror planes are grid planes.
 *
 * <p>Bone nodes are the grid nodes at least {@code softLayers} layers inside the grid's boundary.
 */
public final class FingertipMesher {

    private FingertipMesher() {
    }

    public static TetMesh generate(double a, double b, double c, int nx, int ny, int nz, int softLayers) {
        for (int n : new int[] {nx, ny, nz}) {
            if (n < 3 || n % 2 == 0) {
                throw new IllegalArgumentException("fingertip grid counts must be odd and at least 3, got " + nx + " x " + ny + " x " + nz);
            }
        }
        double[] v = new double[3 * nx * ny * nz];
        boolean[] bone = new boolean[nx * ny * nz];
        for (int k = 0; k < nz; k++) {
            for (int j = 0; j < ny; j++) {
                for (int i = 0; i < nx; i++) {
                    double x = -1 + 2.0 * i / (nx - 1);
                    double y = -1 + 2.0 * j / (ny - 1);
                    double z = -1 + 2.0 * k / (nz - 1);
                    int id = index(i, j, k, nx, ny);
                    v[3 * id] = a * x * Math.sqrt(1 - y * y / 2 - z * z / 2 + y * y * z * z / 3);
                    v[3 * id + 1] = b * y * Math.sqrt(1 - z * z / 2 - x * x / 2 + z * z * x * x / 3);
                    v[3 * id + 2] = c * z * Math.sqrt(1 - x * x / 2 - y * y / 2 + x * x * y * y / 3);
                    int depth = Math.min(Math.min(Math.min(i, nx - 1 - i), Math.min(j, ny - 1 - j)), Math.min(k, nz - 1 - k));
                    bone[id] = depth >= softLayers;
                }
            }
        }
        int cells = (nx - 1) * (ny - 1) * (nz - 1);
        int[] tets = new int[24 * cells];
        int at = 0;
        int[][] perms = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
        int cx = (nx - 1) / 2;
        int cy = (ny - 1) / 2;
        int cz = (nz - 1) / 2;
        for (int k = 0; k < nz - 1; k++) {
            for (int j = 0; j < ny - 1; j++) {
                for (int i = 0; i < nx - 1; i++) {
                    // the cell's inner corner and outward directions in its octant
                    int[] dir = {i >= cx ? 1 : -1, j >= cy ? 1 : -1, k >= cz ? 1 : -1};
                    int[] start = {dir[0] > 0 ? i : i + 1, dir[1] > 0 ? j : j + 1, dir[2] > 0 ? k : k + 1};
                    for (int[] p : perms) {
                        int[] cur = start.clone();
                        int[] tet = new int[4];
                        tet[0] = index(cur[0], cur[1], cur[2], nx, ny);
                        for (int s = 0; s < 3; s++) {
                            cur[p[s]] += dir[p[s]];
                            tet[s + 1] = index(cur[0], cur[1], cur[2], nx, ny);
                        }
                        if (signedVolume(v, tet) < 0) {
                            int t = tet[2];
                            tet[2] = tet[3];
                            tet[3] = t;
                        }
                        System.arraycopy(tet, 0, tets, at, 4);
                        at += 4;
                    }
                }
            }
        }
        return new TetMesh(v, tets, bone);
    }

    private static int index(int i, int j, int k, int nx, int ny) {
        return i + nx * (j + ny * k);
    }

    static double signedVolume(double[] v, int[] t) {
        double[] e = new double[9];
        for (int s = 0; s < 3; s++) {
            for (int c = 0; c < 3; c++) {
                e[3 * s + c] = v[3 * t[s + 1] + c] - v[3 * t[0] + c];
            }
        }
        return (e[0] * (e[4] * e[8] - e[5] * e[7]) - e[1] * (e[3] * e[8] - e[5] * e[6]) + e[2] * (e[3] * e[7] - e[4] * e[6])) / 6;
    }
}
