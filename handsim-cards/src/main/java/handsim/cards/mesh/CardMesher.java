package handsim.cards.mesh;

import java.util.ArrayList;
import java.util.List;

/**
 * The playing card's mid-surface: a regular grid of nx x ny cells over width x height (metres),
 * centred at the origin in the xy-plane, each cell split into two triangles. A rounded corner
 * replaces the corner vertex by {@code ARC_POINTS} points on a quarter ellipse through the two
 * neighbouring boundary vertices, fanned from the inner grid vertex: five triangles instead of
 * two (thesis Fig. 3.6). Card Snapping uses sharp corners (thesis 4.2.4).
 *
 * <p>Counts: a sharp grid has (nx+1)(ny+1) vertices and 2 nx ny triangles; each rounded corner
 * adds three of each. An 11 x 6 grid gives 84 / 132 sharp, 96 / 144 with four rounded corners,
 * and the thesis' 93 vertices / 141 triangles with three.
 */
public final class CardMesher {

    /** Arc points replacing a rounded corner's vertex. */
    public static final int ARC_POINTS = 4;

    private CardMesher() {
    }

    /**
     * @param rounded which corners are rounded, in the order (−x−y, +x−y, +x+y, −x+y)
     */
    public static ShellMesh generate(double width, double height, int nx, int ny, boolean[] rounded) {
        if (nx < 2 || ny < 2) {
            throw new IllegalArgumentException("a card needs at least 2 x 2 cells, got " + nx + " x " + ny);
        }
        if (rounded.length != 4) {
            throw new IllegalArgumentException("rounded needs 4 entries, got " + rounded.length);
        }
        double cx = width / nx;
        double cy = height / ny;
        List<double[]> verts = new ArrayList<>();
        int[][] id = new int[nx + 1][ny + 1];
        // corner grid vertices and the cells they sit in
        int[][] corners = {{0, 0}, {nx, 0}, {nx, ny}, {0, ny}};
        for (int j = 0; j <= ny; j++) {
            for (int i = 0; i <= nx; i++) {
                id[i][j] = -1;
                boolean skip = false;
                for (int c = 0; c < 4; c++) {
                    skip |= rounded[c] && corners[c][0] == i && corners[c][1] == j;
                }
                if (!skip) {
                    id[i][j] = verts.size();
                    verts.add(new double[] {-width / 2 + i * cx, -height / 2 + j * cy, 0});
                }
            }
        }
        List<int[]> tris = new ArrayList<>();
        for (int j = 0; j < ny; j++) {
            for (int i = 0; i < nx; i++) {
                int corner = cornerOfCell(i, j, nx, ny);
                if (corner >= 0 && rounded[corner]) {
                    continue;
                }
                int a = id[i][j];
                int b = id[i + 1][j];
                int c = id[i + 1][j + 1];
                int d = id[i][j + 1];
                tris.add(new int[] {a, b, c});
                tris.add(new int[] {a, c, d});
            }
        }
        for (int c = 0; c < 4; c++) {
            if (!rounded[c]) {
                continue;
            }
            int gi = corners[c][0];
            int gj = corners[c][1];
            int si = gi == 0 ? 1 : -1; // direction from the corner into the card
            int sj = gj == 0 ? 1 : -1;
            int inner = id[gi + si][gj + sj];
            int alongX = id[gi + si][gj];
            int alongY = id[gi][gj + sj];
            double[] centre = verts.get(inner);
            // arc from the x-neighbour to the y-neighbour around the inner vertex
            List<Integer> arc = new ArrayList<>();
            arc.add(alongX);
            for (int k = 1; k <= ARC_POINTS; k++) {
                double phi = 0.5 * Math.PI * k / (ARC_POINTS + 1);
                double x = centre[0] - si * cx * Math.sin(phi);
                double y = centre[1] - sj * cy * Math.cos(phi);
                arc.add(verts.size());
                verts.add(new double[] {x, y, 0});
            }
            arc.add(alongY);
            for (int k = 0; k + 1 < arc.size(); k++) {
                int p = arc.get(k);
                int q = arc.get(k + 1);
                // counter-clockwise seen from +z
                if (si * sj > 0) {
                    tris.add(new int[] {inner, q, p});
                } else {
                    tris.add(new int[] {inner, p, q});
                }
            }
        }
        double[] v = new double[3 * verts.size()];
        for (int k = 0; k < verts.size(); k++) {
            System.arraycopy(verts.get(k), 0, v, 3 * k, 3);
        }
        int[] t = tris.stream().flatMapToInt(java.util.Arrays::stream).toArray();
        return new ShellMesh(v, t);
    }

    private static int cornerOfCell(int i, int j, int nx, int ny) {
        if (i == 0 && j == 0) {
            return 0;
        } else if (i == nx - 1 && j == 0) {
            return 1;
        } else if (i == nx - 1 && j == ny - 1) {
            return 2;
        } else if (i == 0 && j == ny - 1) {
            return 3;
        }
        return -1;
    }
}
