package handsim.cards.sleight;

import handsim.cards.sim.CardsConfig;
import handsim.cards.sim.CardsConfig.Materials;
import handsim.cards.sim.SimState;
import handsim.cards.sim.Simulator;
import handsim.cards.sim.SolverSettings;
import handsim.cards.sim.StepStats;
import java.nio.file.Path;

/**
 * One Card Snapping trial (thesis 4.2.4) as a function of its parameters: the entry point an
 * optimiser calls. The hold (warm-up) is simulated once per {@code SnapTrial} and kept as the
 * checkpoint every trial starts from (thesis 4.2.2); a trial then runs the bone trajectory for
 * the configured duration and returns the end angle between the cards and |α_target − α_end|.
 * Same parameters give bit-identical trajectories. Safe to call from several threads: each trial
 * builds its own simulator.
 */
public final class SnapTrial {

    private final SnapScene scene;
    private final SolverSettings settings;
    private SimState held;

    public SnapTrial(SnapConfig config, Materials materials, SolverSettings settings) {
        this.scene = new SnapScene(config, materials, settings);
        this.settings = settings;
    }

    /**
     * The trial of the project's configs: configs/cards/{snap,materials,solver}.json under
     * {@code home}, with an optional fingertip resolution ("thesis", "reduced") and card preset.
     */
    public static SnapTrial fromConfigs(Path home, String mesh, String cardPreset) {
        Path dir = home.resolve("configs/cards");
        return new SnapTrial(SnapConfig.load(dir.resolve("snap.json"), mesh),
                CardsConfig.materials(dir.resolve("materials.json"), cardPreset),
                CardsConfig.solver(dir.resolve("solver.json")));
    }

    public SnapScene scene() {
        return scene;
    }

    public SolverSettings settings() {
        return settings;
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
            Simulator sim = new Simulator(scene.world(), settings, scene.motion(null))
                    .withGravityScale(t -> SnapScene.ease(t, 0.5 * warmup, warmup));
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
        Simulator sim = new Simulator(scene.world(), settings, scene.motion(params));
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
        return new SnapResult(alpha, Math.abs(c.alphaTargetDegrees() - alpha), minGap, total.steps,
                total.newtonIterations, steps * settings.timeStep(), wall, total.assemblyNanos * 1e-9,
                total.contactNanos * 1e-9, total.solveNanos * 1e-9, total.maxContacts);
    }
}
