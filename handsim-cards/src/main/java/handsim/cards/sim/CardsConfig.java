package handsim.cards.sim;

import handsim.cards.contact.CollisionMesh.FrictionTable;
import handsim.cards.linalg.SparseSpdSystem;
import handsim.config.Json;
import java.nio.file.Path;

/**
 * Reads configs/cards/solver.json and configs/cards/materials.json, validating every field
 * (errors name the file, the field and the bad value).
 */
public final class CardsConfig {

    private CardsConfig() {
    }

    public static SolverSettings solver(Path file) {
        return solver(Json.load(file));
    }

    public static SolverSettings solver(Json j) {
        j.allow("comment", "fields");
        Json f = j.get("friction");
        f.allow("comment");
        SolverSettings s = new SolverSettings(
                j.number("timeStep", 1e-5, 0.1),
                j.number("dhat", 1e-7, 1e-2),
                j.number("newtonTolerance", 1e-9, 1.0),
                j.integer("maxNewtonIterations", 1, 10_000),
                j.number("cgTolerance", 1e-12, 0.5),
                j.integer("cgMaxIterations", 0, 1000),
                j.number("ccdRescaling", 0.1, 1.0),
                new FrictionTable(f.number("cardCard", 0, 5), f.number("skin", 0, 5), f.number("ground", 0, 5)),
                j.number("frictionEpsV", 1e-8, 1.0),
                j.number("kappaScale", 1e-3, 1e20),
                gravity(j),
                j.number("hashCell", 1e-5, 1.0),
                SparseSpdSystem.Factorisation.valueOf(j.choice("factorisation", "supernodal", "qdldl").toUpperCase(java.util.Locale.ROOT)),
                j.bool("parallel", false),
                j.choice("contactHessian", "projected", "gaussNewton").equals("gaussNewton"));
        f.requireNoUnknownFields();
        j.requireNoUnknownFields();
        return s;
    }

    /**
     * The most gravity a card scene takes (m/s²): ten times the Earth's. Beyond it the pinch that
     * holds a card against its weight would crush the fingertips' soft layers.
     */
    static final double MAX_GRAVITY = 100;

    private static double[] gravity(Json j) {
        double[] g = j.numbers("gravity", 3);
        double magnitude = Math.sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (!(magnitude <= MAX_GRAVITY)) {
            throw j.fieldError("gravity", "its magnitude must be at most " + Json.show(MAX_GRAVITY) + " m/s² (ten times the Earth's), got "
                    + Json.show(magnitude));
        }
        return g;
    }

    /** The card material named by {@code preset} (or the file's default "card" when null) and the fingertip's. */
    public record Materials(String cardPreset, ShellMaterial card, SolidMaterial fingertip) {
    }

    public static Materials materials(Path file, String preset) {
        return materials(Json.load(file), preset);
    }

    public static Materials materials(Json j, String preset) {
        j.allow("comment");
        String name = j.string("card");
        Json cards = j.get("cards");
        ShellMaterial chosen = null;
        String wanted = preset != null ? preset : name;
        for (String key : cards.fieldNames()) {
            Json m = cards.get(key);
            m.allow("comment");
            ShellMaterial shell = new ShellMaterial(m.number("density", 1, 1e5), m.number("young", 1, 1e13),
                    m.number("poisson", 0, 0.499), m.number("thickness", 1e-6, 0.01));
            m.requireNoUnknownFields();
            if (key.equals(wanted)) {
                chosen = shell;
            }
        }
        if (chosen == null) {
            throw (preset != null ? j.error("card preset \"" + preset + "\" is not among " + cards.fieldNames())
                    : j.fieldError("card", "\"" + name + "\" is not among " + cards.fieldNames()));
        }
        Json t = j.get("fingertip");
        t.allow("comment");
        SolidMaterial tip = new SolidMaterial(t.number("density", 1, 1e5), t.number("young", 1, 1e13), t.number("poisson", 0, 0.49));
        t.requireNoUnknownFields();
        j.requireNoUnknownFields();
        return new Materials(wanted, chosen, tip);
    }
}
