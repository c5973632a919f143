package handsim.cards.sleight;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.sim.CardsConfig;
import handsim.cards.sim.CardsConfig.Materials;
import handsim.cards.sim.SimState;
import handsim.cards.sim.SoftSimulator;
import handsim.cards.sim.SoftWorld;
import handsim.cards.sim.SolverSettings;
import handsim.cards.sim.TrialBudget;
import handsim.cards.sim.StepStats;
import handsim.cards.study.StudyConfig;
import handsim.config.ConfigException;
import handsim.config.Json;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;

/**
 * One Double Lift trial (thesis 4.2.5, eq. 4.6) as a function of its parameters. The stack is
 * warmed up once until it rests and kept as a checkpoint on disk, keyed by the configs it
 * depends on ({@link StackCheckpoint}), which every trial starts from (thesis 4.2.2). A trial
 * places the fingertips hStart above the stack, pinches, lifts, and holds still to the end; it
 * returns (|h1 − h_target|, |h2 − h_target|, ‖d3‖), all minimised: the rise of the top two cards'
 * centroids against the target, and how far the third card's centroid moved. Same parameters
 * give bit-identical trials; each call builds its own simulator, so trials may run on several
 * threads.
 */
public final class LiftTrial implements CardSleight {

    public static final List<String> PARAMS = List.of("hStart", "t0", "t1", "vp", "t2", "t3", "vs");

    private final LiftScene scene;
    private final SolverSettings settings;
    private final TrialBudget budget;
    private final ObjectNode inputs;
    private final JsonNode checkpointKey;
    private final Path checkpointFile;
    private Consumer<String> log = line -> { };
    private SimState rested;

    LiftTrial(LiftConfig config, Materials materials, SolverSettings settings, TrialBudget budget, ObjectNode inputs, JsonNode checkpointKey,
              Path checkpoints) {
        this.scene = new LiftScene(config, materials, settings);
        this.settings = settings;
        this.budget = budget;
        this.inputs = inputs;
        this.checkpointKey = checkpointKey;
        this.checkpointFile = checkpoints == null ? null : StackCheckpoint.file(checkpoints, "double-lift", checkpointKey);
    }

    /**
     * The trial of configs/cards/{double-lift,materials,solver,budget}.json under {@code home} with fields
     * overridden by dotted path ({@code "double-lift.trial.hTarget" -> "0.004"}), an optional
     * fingertip resolution and card preset; the rested stack is kept in {@code checkpoints}
     * (null: in memory only).
     */
    public static LiftTrial fromConfigs(Path home, String mesh, String cardPreset, Map<String, String> overrides, Path checkpoints) {
        return (LiftTrial) Sleights.fromConfigs("double-lift", home, mesh, cardPreset, overrides, checkpoints);
    }

    /** Where progress lines of the warm-up go (none by default). */
    public LiftTrial withLog(Consumer<String> log) {
        this.log = log;
        return this;
    }

    public LiftScene scene() {
        return scene;
    }

    /** The checkpoint file of this trial's rested stack (null when kept in memory only). */
    public Path checkpointFile() {
        return checkpointFile;
    }

    /**
     * The rested stack every trial starts from: read from its checkpoint when one was made for
     * these configs, else warmed up (and written).
     */
    public synchronized SimState restedStack() {
        if (rested == null) {
            try {
                if (checkpointFile != null && Files.exists(checkpointFile)) {
                    rested = StackCheckpoint.read(checkpointFile, checkpointKey);
                    log.accept("rested stack read from " + checkpointFile);
                } else {
                    rested = warmUp();
                    if (checkpointFile != null) {
                        StackCheckpoint.write(checkpointFile, checkpointKey, rested);
                        log.accept("rested stack written to " + checkpointFile);
                    }
                }
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return rested.copy();
    }

    /** Lets the stack fall onto the table from its stacked gaps until no node moves faster than restSpeed for restSteps steps. */
    SimState warmUp() {
        LiftConfig c = scene.config();
        SimState s = scene.stackWorld().restState();
        SoftSimulator sim = new SoftSimulator(scene.stackWorld(), settings, handsim.cards.sim.BoneMotion.STILL).withBudget(budget, c.warmupLimit());
        int still = 0;
        long t0 = System.nanoTime();
        while (still < c.restSteps()) {
            if (s.time > c.warmupLimit()) {
                throw new IllegalStateException("the stack of " + c.count() + " cards still moves after " + c.warmupLimit()
                        + " s of warm-up (stack.warmupLimit)");
            }
            StepStats st = sim.step(s);
            double fastest = 0;
            for (double v : s.v) {
                fastest = Math.max(fastest, Math.abs(v));
            }
            still = fastest <= c.restSpeed() ? still + 1 : 0;
            log.accept(String.format(Locale.ROOT, "warm-up step %d: %.2f s simulated, fastest node %.2e m/s, %d Newton iterations, "
                    + "%d contacts, min gap %.2e m (%.0f s wall)", s.steps, s.time, fastest, st.newtonIterations, st.maxContacts, st.minGap,
                    (System.nanoTime() - t0) * 1e-9));
        }
        return s;
    }

    @Override
    public SimState startState(Map<String, Double> params) {
        return scene.startState(restedStack(), LiftParams.of(params).hStart());
    }

    /** One trial from the rested stack. */
    public LiftResult run(LiftParams p, TrialCost.StepListener listener) {
        LiftConfig c = scene.config();
        p.validate(c.lastLiftEnd(), null);
        SimState start = scene.startState(restedStack(), p.hStart());
        SimState state = start.copy();
        SoftSimulator sim = new SoftSimulator(scene.world(), settings, scene.motion(p)).withBudget(budget, c.duration());
        int steps = (int) Math.round(c.duration() / settings.timeStep());
        TrialCost cost = TrialCost.simulate(sim, state, steps, settings.timeStep(), listener);
        return new LiftResult(scene.rise(start, state, 1), scene.rise(start, state, 2), scene.rise(start, state, 3),
                scene.displacement(start, state, 3), c.hTarget(), cost);
    }

    @Override
    public Outcome run(Map<String, Double> params, TrialCost.StepListener listener) {
        LiftResult r = run(LiftParams.of(params), listener);
        Map<String, Double> figures = new LinkedHashMap<>();
        figures.put("h1", r.h1());
        figures.put("h2", r.h2());
        figures.put("h3", r.h3());
        figures.put("d3", r.d3());
        List<String> report = List.of(
                String.format(Locale.ROOT, "h1, h2      %.3f, %.3f mm risen (target %.3f mm): |h1 - h_target| %.3f mm, |h2 - h_target| %.3f mm",
                        1e3 * r.h1(), 1e3 * r.h2(), 1e3 * r.hTarget(), 1e3 * r.values()[0], 1e3 * r.values()[1]),
                String.format(Locale.ROOT, "card 3      moved %.3f mm (risen %.3f mm)", 1e3 * r.d3(), 1e3 * r.h3()));
        return new Outcome(r.values(), figures, r.cost(), report);
    }

    @Override
    public String name() {
        return "double-lift";
    }

    @Override
    public String title() {
        return "Double Lift";
    }

    @Override
    public SoftWorld world() {
        return scene.world();
    }

    @Override
    public ObjectNode inputs() {
        return inputs.deepCopy();
    }

    @Override
    public String meshName() {
        return scene.config().meshName();
    }

    @Override
    public List<String> paramNames() {
        return PARAMS;
    }

    @Override
    public Map<String, Double> defaults() {
        return scene.config().defaults().byName();
    }

    @Override
    public Map<String, Double> parseParams(Json j) {
        LiftParams p = LiftParams.parse(j);
        p.validate(scene.config().lastLiftEnd(), j.source());
        return p.byName();
    }

    @Override
    public int frameEvery() {
        return scene.config().frameEvery();
    }

    /**
     * Three objectives, the seven parameters (linear floats), windows that cannot overlap, the
     * lift over at least restAfterLift before the trial ends (thesis 4.2.5), lifts upwards.
     */
    @Override
    public void checkSearchSpace(StudyConfig c, String source) {
        if (c.objectives().size() != 3) {
            throw new ConfigException(source + ": objectives: Double Lift has three objectives (eq. 4.6), got " + c.objectives());
        }
        BoneWindows.checkSearchSpace(c, PARAMS, scene.config().lastLiftEnd(), title(), source);
        for (handsim.cards.tpe.Param q : c.params()) {
            if (q.name().equals("hStart") && !(Math.max(-q.low(), q.high()) <= LiftParams.MAX_START_HEIGHT)) {
                throw new ConfigException(source + ": params: hStart's range must lie within +-" + LiftParams.MAX_START_HEIGHT
                        + " m of the stack's top, got [" + q.low() + ", " + q.high() + "]");
            }
        }
    }
}
