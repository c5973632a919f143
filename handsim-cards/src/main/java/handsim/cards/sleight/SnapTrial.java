package handsim.cards.sleight;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.sim.CardsConfig;
import handsim.cards.sim.CardsConfig.Materials;
import handsim.cards.sim.SimState;
import handsim.cards.sim.SoftSimulator;
import handsim.cards.sim.SolverSettings;
import handsim.cards.sim.SoftWorld;
import handsim.cards.sim.TrialBudget;
import handsim.cards.study.StudyConfig;
import handsim.config.ConfigException;
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
public final class SnapTrial implements CardSleight {

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

    SnapTrial(SnapConfig config, Materials materials, SolverSettings settings, TrialBudget budget, ObjectNode inputs) {
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
        return (SnapTrial) Sleights.fromConfigs("snap", home, mesh, cardPreset, overrides, null);
    }

    /**
     * What this trial was built from, for a study's record: the sleight, fingertip mesh and card
     * preset, snap.json (with any overrides), materials.json and solver.json as read, and the
     * budget; empty for a trial built from records.
     */
    @Override
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

    /** The rested hold every trial starts from (simulated on first use). */
    public synchronized SimState heldState() {
        if (held == null) {
            SimState s = scene.world().restState();
            double warmup = scene.config().warmup();
            // gravity ramps on over the second half of the warm-up, once the bones hold the cards
            SoftSimulator sim = new SoftSimulator(scene.world(), settings, scene.motion(null))
                    .withGravityScale(t -> BoneWindows.ease(t, 0.5 * warmup, warmup)).withBudget(budget, warmup);
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

    public SnapResult run(SnapParams params, TrialCost.StepListener listener) {
        SnapConfig c = scene.config();
        params.validate(c.duration(), null);
        SimState state = heldState();
        SoftSimulator sim = new SoftSimulator(scene.world(), settings, scene.motion(params)).withBudget(budget, c.duration());
        int steps = (int) Math.round(c.duration() / settings.timeStep());
        TrialCost cost = TrialCost.simulate(sim, state, steps, settings.timeStep(), listener);
        double alpha = scene.angleBetweenCards(state);
        double drop = scene.cardDrop(heldState(), state);
        // a card that fell out of the fingers was not snapped: the largest error, whatever its angle
        boolean held = drop <= c.dropLimit();
        double objective = held ? Math.abs(c.alphaTargetDegrees() - alpha) : c.droppedObjective();
        return new SnapResult(alpha, objective, drop, held, cost);
    }

    @Override
    public String name() {
        return "snap";
    }

    @Override
    public String title() {
        return "Card Snapping";
    }

    @Override
    public SoftWorld world() {
        return scene.world();
    }

    @Override
    public String meshName() {
        return scene.config().meshName();
    }

    @Override
    public List<String> paramNames() {
        return BoneWindows.NAMES;
    }

    @Override
    public Map<String, Double> defaults() {
        return scene.config().defaults().byName();
    }

    @Override
    public Map<String, Double> parseParams(Json j) {
        SnapParams p = SnapParams.parse(j);
        p.validate(scene.config().duration(), j.source());
        return p.byName();
    }

    @Override
    public SimState startState(Map<String, Double> params) {
        return heldState();
    }

    @Override
    public int frameEvery() {
        return scene.config().frameEvery();
    }

    /**
     * Card Snapping minimises |α_target − α_end| in degrees (a dropped card scores the largest
     * error); the end angle, the card drop and whether the cards were held are kept as figures.
     */
    @Override
    public Outcome run(Map<String, Double> params, TrialCost.StepListener listener) {
        SnapResult r = run(SnapParams.of(BoneWindows.of(params)), listener);
        Map<String, Double> figures = new java.util.LinkedHashMap<>();
        figures.put("alphaEnd", r.alphaEnd());
        figures.put("cardDrop", r.cardDrop());
        figures.put("held", r.held() ? 1.0 : 0.0);
        SnapConfig c = scene.config();
        List<String> report = List.of(
                String.format(java.util.Locale.ROOT, "alpha_end   %.3f deg (target %s)", r.alphaEnd(), Json.show(c.alphaTargetDegrees())),
                String.format(java.util.Locale.ROOT, "objective   %.3f deg", r.objective()),
                String.format(java.util.Locale.ROOT, "card drop   %.2f mm below the hold at the end (%s)", 1e3 * r.cardDrop(),
                        r.held() ? "held" : "DROPPED: no snap"));
        return new Outcome(new double[] {r.objective()}, figures, r.cost(), report);
    }

    /**
     * One objective, the six window parameters (linear floats) whose windows cannot overlap, t3
     * within the trial (thesis 4.2.4).
     */
    @Override
    public void checkSearchSpace(StudyConfig c, String source) {
        if (c.objectives().size() != 1) {
            throw new ConfigException(source + ": objectives: Card Snapping has one objective, got " + c.objectives());
        }
        BoneWindows.checkSearchSpace(c, paramNames(), scene.config().duration(), title(), source);
    }
}
