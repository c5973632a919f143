package handsim.cards.sleight;

import handsim.config.Json;
import java.nio.file.Path;

/** The Card Snapping scene from configs/cards/snap.json, validated field by field. */
public record SnapConfig(double cardLength, double cardWidth, int cellsLong, int cellsShort, int roundedCorners,
                         double gapFraction, double[] semiAxes, String meshName, int[] grid, int softLayers,
                         double pinchBelowTop, double initialGap, double holdDepth, double warmup,
                         double duration, double alphaTargetDegrees, double dropLimit, double droppedObjective,
                         int frameEvery, SnapParams defaults) {

    /*
     * Physical and practical ranges beyond those the fields state: a fingertip's semi-axes from
     * 1 mm (a needle, not a finger) to 5 cm (larger than any finger; the thesis' are 6-12 mm);
     * at most 41 grid points an axis (41^3 = 68,921 nodes a fingertip, 20 times the thesis'
     * 17 x 11 x 9) and 200 cells a card side (0.44 mm cells on a playing card, against the
     * thesis' 11 x 6): finer meshes exhaust memory long before they change the snap.
     */
    static final double MIN_SEMI_AXIS = 1e-3, MAX_SEMI_AXIS = 0.05;
    static final int MAX_GRID = 41, MAX_CELLS = 200;

    public static SnapConfig load(Path file) {
        return parse(Json.load(file), null);
    }

    /** @param mesh a fingertip resolution overriding the file's ("thesis", "reduced"), or null */
    public static SnapConfig load(Path file, String mesh) {
        return parse(Json.load(file), mesh);
    }

    public static SnapConfig parse(Json j, String meshOverride) {
        j.allow("comment");
        Json card = j.get("card");
        card.allow("comment");
        int[] cells = ints(card, "cells", 2);
        Json tip = j.get("fingertip");
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
            int[] g = ints(meshes, name, 3);
            for (int v : g) {
                if (v < 3 || v > MAX_GRID || v % 2 == 0) {
                    throw meshes.fieldError(name, "grid counts must be odd and in [3, " + MAX_GRID + "], got " + java.util.Arrays.toString(g));
                }
            }
            if (name.equals(chosen)) {
                grid = g;
            }
        }
        Json hold = j.get("hold");
        hold.allow("comment");
        Json trial = j.get("trial");
        trial.allow("comment");
        double duration = trial.number("duration", 0.01, 100);
        SnapParams defaults = SnapParams.parse(j.get("params"));
        defaults.validate(duration, j.source() + ": params");
        SnapConfig c = new SnapConfig(
                card.number("length", 1e-3, 1), card.number("width", 1e-3, 1), cells[0], cells[1],
                card.integer("roundedCorners", 0, 4), card.number("gapFraction", 0, 10),
                tip.numbers("semiAxes", 3), chosen, grid, tip.integer("softLayers", 1, 100),
                tip.number("pinchBelowTop", 0, 1),
                hold.number("initialGap", 0, 0.01), hold.number("depth", 0, 0.01), hold.number("warmup", 0, 10),
                duration, trial.number("alphaTarget", 0, 180), trial.number("dropLimit", 0, 10), trial.number("droppedObjective", 0, 1e6),
                trial.integer("frameEvery", 1, 10_000),
                defaults);
        for (double a : c.semiAxes) {
            if (!(a >= MIN_SEMI_AXIS && a <= MAX_SEMI_AXIS)) {
                throw tip.fieldError("semiAxes", "each must be in [" + Json.show(MIN_SEMI_AXIS) + ", " + Json.show(MAX_SEMI_AXIS)
                        + "] m, got " + java.util.Arrays.toString(c.semiAxes));
            }
        }
        if (cells[0] < 2 || cells[1] < 2 || cells[0] > MAX_CELLS || cells[1] > MAX_CELLS) {
            throw card.fieldError("cells", "need 2 to " + MAX_CELLS + " a side, got " + java.util.Arrays.toString(cells));
        }
        if (c.pinchBelowTop > c.cardLength) {
            throw tip.fieldError("pinchBelowTop", "must be within the card's length " + Json.show(c.cardLength) + " m, got "
                    + Json.show(c.pinchBelowTop));
        }
        for (Json node : new Json[] {card, tip, hold, trial, j}) {
            node.requireNoUnknownFields();
        }
        return c;
    }

    private static int[] ints(Json j, String name, int n) {
        double[] v = j.numbers(name, n);
        int[] out = new int[n];
        for (int i = 0; i < n; i++) {
            if (v[i] != Math.rint(v[i])) {
                throw j.fieldError(name, "expected whole numbers, got " + java.util.Arrays.toString(v));
            }
            out[i] = (int) v[i];
        }
        return out;
    }
}
