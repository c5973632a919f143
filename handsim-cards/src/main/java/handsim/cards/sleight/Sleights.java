package handsim.cards.sleight;

import com.fasterxml.jackson.databind.JsonNode;
import handsim.cards.sim.CardsConfig;
import handsim.cards.sim.CardsConfig.Materials;
import handsim.cards.sim.TrialBudget;
import handsim.config.ConfigException;
import handsim.config.Json;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * The card sleights by name: snap (Card Snapping, thesis 4.2.4) and double-lift (Double Lift,
 * 4.2.5), built from the project's configs or from what a study recorded of them ({@link
 * CardSleight#inputs()}), so that a trial can be run again, anywhere, from the record alone.
 */
public final class Sleights {

    public static final List<String> NAMES = List.of("snap", "double-lift");

    private Sleights() {
    }

    /**
     * The sleight {@code name} of configs/cards/{NAME,materials,solver,budget}.json under {@code home}
     * with {@code overrides} (dotted keys starting with the file's name), an optional fingertip
     * mesh and card preset; a rested stack is kept in {@code checkpoints} (null: in memory).
     */
    public static CardSleight fromConfigs(String name, Path home, String mesh, String cardPreset, Map<String, String> overrides,
                                          Path checkpoints) {
        requireKnown(name);
        return build(SleightFiles.load(home, name, overrides), mesh, cardPreset, checkpoints);
    }

    /**
     * The sleight a study recorded ({@code inputs}: sleight, mesh, card and the three configs as
     * read, and the budget), with the fingertip mesh {@code meshOverride} instead when not null. A
     * study recorded without a budget is replayed without one ({@link TrialBudget#UNLIMITED}).
     */
    public static CardSleight fromInputs(JsonNode inputs, String meshOverride, Path checkpoints) {
        Json in = Json.of("the study's objective", inputs);
        String name = in.string("sleight");
        requireKnown(name);
        SleightFiles files = new SleightFiles(name, in.get(name), in.get("materials"), in.get("solver"),
                in.has("budget") ? in.get("budget") : Json.of("no budget", TrialBudget.UNLIMITED.toJson()));
        return build(files, meshOverride != null ? meshOverride : in.string("mesh"), in.string("card"), checkpoints);
    }

    private static CardSleight build(SleightFiles files, String mesh, String cardPreset, Path checkpoints) {
        Materials materials = CardsConfig.materials(files.materials(), cardPreset);
        var solver = CardsConfig.solver(files.solver());
        TrialBudget budget = files.budget();
        if (files.sceneName().equals("snap")) {
            SnapConfig config = SnapConfig.parse(files.scene(), mesh);
            return new SnapTrial(config, materials, solver, budget, files.inputs("snap", config.meshName(), materials.cardPreset()));
        }
        LiftConfig config = LiftConfig.parse(files.scene(), mesh);
        return new LiftTrial(config, materials, solver, budget, files.inputs("double-lift", config.meshName(), materials.cardPreset()),
                StackCheckpoint.dependsOn(files, materials.cardPreset()), checkpoints);
    }

    private static void requireKnown(String name) {
        if (!NAMES.contains(name)) {
            throw new ConfigException("sleight must be one of " + String.join(", ", NAMES) + ", got \"" + name + "\"");
        }
    }
}
