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
                if (v < 3 || v % 2 == 0) {
                    throw meshes.fieldError(name, "grid counts must be odd and >= 3, got " + java.util.Arrays.toString(g));
                }
            }
            if (name.equals(chosen)) {
                grid = g;
            }
        }
        double[] axes = tip.numbers("semiAxes", 3);
        for (double a : axes) {
            if (!(a > 0)) {
                throw tip.fieldError("semiAxes", "must be positive, got " + java.util.Arrays.toString(axes));
            }
        }
        return new FingertipSpec(axes, chosen, grid, tip.integer("softLayers", 1, 100));
    }

    /** The tetrahedral ellipsoid in its own frame (x along the finger, z towards the pad). */
    public TetMesh mesh() {
        return FingertipMesher.generate(semiAxes[0], semiAxes[1], semiAxes[2], grid[0], grid[1], grid[2], softLayers);
    }
}
