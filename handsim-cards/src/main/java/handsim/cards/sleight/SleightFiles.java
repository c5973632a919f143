package handsim.cards.sleight;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.sim.TrialBudget;
import handsim.config.Json;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The config files a sleight's trial is built from, read with fields overridden by dotted path:
 * configs/cards/SCENE.json (the sleight's scene), materials.json, solver.json and budget.json
 * (what one simulation may use, {@link TrialBudget}). An
 * override's key starts with the file it changes: {@code "snap.trial.duration" -> "0.3"},
 * {@code "solver.parallel" -> "false"} (values in JSON). A scene's own {@code solver} object sets
 * fields of solver.json for that sleight; the solver file is kept as the trial reads it.
 */
record SleightFiles(String sceneName, Json scene, Json materials, Json solver, Json budgetFile) {

    static SleightFiles load(Path home, String sceneName, Map<String, String> overrides) {
        Path dir = home.resolve("configs/cards");
        Map<String, Map<String, String>> byFile = new LinkedHashMap<>();
        for (String file : List.of(sceneName, "materials", "solver", "budget")) {
            byFile.put(file, new LinkedHashMap<>());
        }
        overrides.forEach((key, value) -> {
            Map<String, String> target = null;
            for (String file : byFile.keySet()) {
                if (key.startsWith(file + ".")) {
                    target = byFile.get(file);
                    target.put(key.substring(file.length() + 1), value);
                }
            }
            if (target == null) {
                throw new IllegalArgumentException("--set " + key + ": the key must start with " + sceneName + "., materials., solver. or budget.");
            }
        });
        Json scene = Json.load(dir.resolve(sceneName + ".json"), byFile.get(sceneName));
        Map<String, String> solver = new LinkedHashMap<>(sceneSolverFields(scene));
        solver.putAll(byFile.get("solver")); // a --set of solver.json wins over the scene's own choice
        return new SleightFiles(sceneName, scene, Json.load(dir.resolve("materials.json"), byFile.get("materials")),
                Json.load(dir.resolve("solver.json"), solver), Json.load(dir.resolve("budget.json"), byFile.get("budget")));
    }

    /**
     * The solver.json fields a scene sets for itself, its optional {@code solver} object (say
     * Double Lift's Gauss–Newton contact Hessians), as overrides in JSON text; comments left out.
     */
    /** What one simulation of the trial may use. */
    TrialBudget budget() {
        return TrialBudget.parse(budgetFile);
    }

    static Map<String, String> sceneSolverFields(Json scene) {
        Map<String, String> out = new LinkedHashMap<>();
        if (scene.has("solver")) {
            scene.get("solver").node().fields().forEachRemaining(f -> {
                if (!f.getKey().equals("comment")) {
                    out.put(f.getKey(), f.getValue().toString());
                }
            });
        }
        return out;
    }

    /**
     * What a trial was built from, for a study's record: the sleight, fingertip mesh and card
     * preset, the scene, materials and solver files as read (with any overrides), and the budget.
     */
    ObjectNode inputs(String sleight, String mesh, String cardPreset) {
        ObjectNode inputs = Json.mapper().createObjectNode();
        inputs.put("sleight", sleight);
        inputs.put("mesh", mesh);
        inputs.put("card", cardPreset);
        inputs.set(sceneName, scene.node().deepCopy());
        inputs.set("materials", materials.node().deepCopy());
        inputs.set("solver", solver.node().deepCopy());
        inputs.set("budget", budget().toJson());
        return inputs;
    }
}
