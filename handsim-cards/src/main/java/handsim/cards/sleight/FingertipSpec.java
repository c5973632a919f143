package handsim.cards.sleight;

import handsim.cards.mesh.FingertipMesher;
import handsim.cards.mesh.TetMesh;
import handsim.config.Json;

/**
 * The fingertips of a sleight's scene (the {@code fingertip} object of its config): the
 * ellipsoid's semi-axes (m) along the finger, across it and towards the pad, the grid points per
 * axis of the chosen mesh resolution, and how many layers of grid nodes under the skin stay
 * soft (the rest is bone, thesis 3.2.3).
 */
public record FingertipSpec(double[] semiAxes, String meshName, int[] grid, int softLayers) {

    /*
     * Physical and practical ranges beyond those the fields state: semi-axes from 1 mm (a needle,
     * not a finger) to 5 cm (larger than any finger; the thesis' are 6-12 mm); at most 41 grid
     * points an axis (41^3 = 68,921 nodes a fingertip, 20 times the thesis' 17 x 11 x 9): finer
     * meshes exhaust memory long before they change a sleight.
     */
    static final double MIN_SEMI_AXIS = 1e-3, MAX_SEMI_AXIS = 0.05;
    static final int MAX_GRID = 41;

    public FingertipSpec {
        semiAxes = semiAxes.clone();
        grid = grid.clone();
    }

    @Override
    public double[] semiAxes() {
        return semiAxes.clone();
    }

    @Override
    public int[] grid() {
        return grid.clone();
    }

    /**
     * Reads the fields of {@code tip} with the mesh resolution {@code meshOverride} instead of the
     * file's when not null; the caller checks for unknown fields once it has read its own.
     */
    static FingertipSpec parse(Json tip, String meshOverride) {
        tip.allow("comment");
        String mesh = tip.string("mesh");
        Json meshes = tip.get("meshes");
        String chosen = meshOverride != null ? meshOverride : mesh;
        if (!meshes.has(chosen)) {
            throw meshOverride != null
                    ? new IllegalArgumentException("fingertip mesh \"" + chosen + "\" is not among " + meshes.fieldNames())
                    : tip.fieldError("mesh", "\"" + chosen + "\" is not among " + meshes.fieldNames());
        }
        int[] grid = null;
        for (String name : meshes.fieldNames()) {
            int[] g = SceneFields.ints(meshes, name, 3);
            for (int v : g) {
                if (v < 3 || v > MAX_GRID || v % 2 == 0) {
                    throw meshes.fieldError(name, "grid counts must be odd and in [3, " + MAX_GRID + "], got " + java.util.Arrays.toString(g));
                }
            }
            if (name.equals(chosen)) {
                grid = g;
            }
        }
        double[] axes = tip.numbers("semiAxes", 3);
        for (double a : axes) {
            if (!(a >= MIN_SEMI_AXIS && a <= MAX_SEMI_AXIS)) {
                throw tip.fieldError("semiAxes", "each must be in [" + Json.show(MIN_SEMI_AXIS) + ", " + Json.show(MAX_SEMI_AXIS)
                        + "] m, got " + java.util.Arrays.toString(axes));
            }
        }
        return new FingertipSpec(axes, chosen, grid, tip.integer("softLayers", 1, 100));
    }

    /** The tetrahedral ellipsoid in its own frame (x along the finger, z towards the pad). */
    public TetMesh mesh() {
        return FingertipMesher.generate(semiAxes[0], semiAxes[1], semiAxes[2], grid[0], grid[1], grid[2], softLayers);
    }
}
