package handsim.cards.sleight;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.sim.CardsConfig;
import handsim.cards.sim.CardsConfig.Materials;
import handsim.cards.sim.SimState;
import handsim.cards.sim.SoftSimulator;
import handsim.cards.sim.SolverSettings;
import handsim.cards.sim.StepStats;
import handsim.cards.sim.TrialBudget;
import handsim.config.Json;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * One Card Snapping trial (thesis 4.2.4) as a function of its parameters: the entry point an
 * optimiser calls. The hold (warm-up) is simulated once per {@code SnapTrial} and kept as the
 * checkpoint every trial starts from (thesis 4.2.2); a trial then runs the bone trajectory for
 * the configured duration and returns the end angle between the cards and |α_target − α_end|
 * (or the configured dropped objective if a card fell out of the fingers).
 * Same parameters give bit-identical trajectories. Safe to call from several threads: each trial
 * builds its own simulator. A simulation past its {@link TrialBudget} throws
 * {@link handsim.cards.contact.BudgetExceeded}.
 */
public final class SnapTrial {

    private final SnapScene scene;
    private final SolverSettings settings;
    private final TrialBudget budget;
    private final ObjectNode inputs;
    private SimState held;

    /** A trial with no budget ({@link TrialBudget#UNLIMITED}). */
    public SnapTrial(SnapConfig config, Materials materials, SolverSettings settings) {
        this(config, materials, settings, TrialBudget.UNLIMITED);
    }

    /** A trial whose simulations (the hold, each run) are limited to {@code budget}. */
    public SnapTrial(SnapConfig config, Materials materials, SolverSettings settings, TrialBudget budget) {
        this(config, materials, settings, budget, Json.mapper().createObjectNode());
    }

    private SnapTrial(SnapConfig config, Materials materials, SolverSettings settings, TrialBudget budget, ObjectNode inputs) {
        this.scene = new SnapScene(config, materials, settings);
        this.settings = settings;
        this.budget = budget;
        this.inputs = inputs;
    }

    /**
     * The trial of the project's configs: configs/cards/{snap,materials,solver,budget}.json under
     * {@code home}, with an optional fingertip resolution ("thesis", "reduced") and card preset.
     */
    public static SnapTrial fromConfigs(Path home, String mesh, String cardPreset) {
        return fromConfigs(home, mesh, cardPreset, Map.of());
    }

    /**
     * {@link #fromConfigs(Path, String, String)} with fields overridden by dotted path, the first
     * part naming the file: {@code "snap.trial.duration" -> "0.3"}, {@code "solver.parallel" ->
     * "false"} (values in JSON; files snap, materials, solver, budget).
     */
    public static SnapTrial fromConfigs(Path home, String mesh, String cardPreset, Map<String, String> overrides) {
        Path dir = home.resolve("configs/cards");
        Map<String, Map<String, String>> byFile = new java.util.LinkedHashMap<>();
        for (String file : List.of("snap", "materials", "solver", "budget")) {
            byFile.put(file, new java.util.LinkedHashMap<>());
        }
        overrides.forEach((key, value) -> {
            int dot = key.indexOf('.');
            Map<String, String> target = dot < 0 ? null : byFile.get(key.substring(0, dot));
            if (target == null) {
                throw new IllegalArgumentException("--set " + key + ": the key must start with snap., materials., solver. or budget.");
            }
            target.put(key.substring(dot + 1), value);
        });
        Json snap = Json.load(dir.resolve("snap.json"), byFile.get("snap"));
        Json materialsFile = Json.load(dir.resolve("materials.json"), byFile.get("materials"));
        Json solverFile = Json.load(dir.resolve("solver.json"), byFile.get("solver"));
        Json budgetFile = Json.load(dir.resolve("budget.json"), byFile.get("budget"));
        SnapConfig config = SnapConfig.parse(snap, mesh);
        Materials materials = CardsConfig.materials(materialsFile, cardPreset);
        ObjectNode inputs = Json.mapper().createObjectNode();
        inputs.put("sleight", "snap");
        inputs.put("mesh", config.meshName());
        inputs.put("card", materials.cardPreset());
        inputs.set("snap", snap.node().deepCopy());
        inputs.set("materials", materialsFile.node().deepCopy());
        inputs.set("solver", solverFile.node().deepCopy());
        TrialBudget budget = TrialBudget.parse(budgetFile);
        inputs.set("budget", budget.toJson());
        return new SnapTrial(config, materials, CardsConfig.solver(solverFile), budget, inputs);
    }

    /**
     * What this trial was built from, for a study's record: the sleight, fingertip mesh and card
     * preset, snap.json (with any overrides), materials.json and solver.json as read, and the
     * budget; empty for a trial built from records.
     */
    public ObjectNode inputs() {
        return inputs.deepCopy();
    }

    public SnapScene scene() {
        return scene;
    }

    public SolverSettings settings() {
        return settings;
    }

    /** What one simulation of this trial may use ({@link TrialBudget}). */
    public TrialBudget budget() {
        return budget;
    }

    /** Receives the state after every step of a trial (for recording frames). */
    public interface StepListener {
        void afterStep(SimState state, StepStats step);
    }

    /** The rested hold every trial starts from (simulated on first use). */
    public synchronized SimState heldState() {
        if (held == null) {
            SimState s = scene.world().restState();
            double warmup = scene.config().warmup();
            // gravity ramps on over the second half of the warm-up, once the bones hold the cards
            SoftSimulator sim = new SoftSimulator(scene.world(), settings, scene.motion(null))
                    .withGravityScale(t -> SnapScene.ease(t, 0.5 * warmup, warmup)).withBudget(budget, warmup);
            int steps = (int) Math.round(scene.config().warmup() / settings.timeStep());
            for (int i = 0; i < steps; i++) {
                sim.step(s);
            }
            held = s;
        }
        return held.copy();
    }

    public SnapResult run(SnapParams params) {
        return run(params, null);
    }

    public SnapResult run(SnapParams params, StepListener listener) {
        SnapConfig c = scene.config();
        params.validate(c.duration(), null);
        SimState state = heldState();
        SoftSimulator sim = new SoftSimulator(scene.world(), settings, scene.motion(params)).withBudget(budget, c.duration());
        int steps = (int) Math.round(c.duration() / settings.timeStep());
        long start = System.nanoTime();
        double minGap = Double.POSITIVE_INFINITY;
        for (int i = 0; i < steps; i++) {
            StepStats st = sim.step(state);
            minGap = Math.min(minGap, st.minGap);
            if (listener != null) {
                listener.afterStep(state, st);
            }
        }
        double wall = (System.nanoTime() - start) * 1e-9;
        StepStats total = sim.stats();
        double alpha = scene.angleBetweenCards(state);
        double drop = scene.cardDrop(heldState(), state);
        // a card that fell out of the fingers was not snapped: the largest error, whatever its angle
        boolean held = drop <= c.dropLimit();
        double objective = held ? Math.abs(c.alphaTargetDegrees() - alpha) : c.droppedObjective();
        return new SnapResult(alpha, objective, minGap, total.steps,
                total.newtonIterations, steps * settings.timeStep(), wall, total.assemblyNanos * 1e-9,
                total.contactNanos * 1e-9, total.solveNanos * 1e-9, total.maxContacts, drop, held);
    }
}
