package handsim.app;

import handsim.config.ConfigSet;
import handsim.config.Home;
import handsim.control.ControllerConfig;
import handsim.control.PdController;
import handsim.model.HandModel;
import handsim.model.ModelLoader;
import handsim.planning.PlannerConfig;
import handsim.rollout.LocalRollouts;
import handsim.rollout.Rollouts;
import handsim.sim.ObjectSpec;
import handsim.sim.SimConfig;
import handsim.sim.Simulator;
import handsim.sim.ode.IsolatedEngine;
import handsim.sim.ode.OdeSimulator;
import handsim.spec.RunConfigs;
import handsim.task.EpisodeLimits;
import handsim.task.LaunchDistribution;
import java.nio.file.Path;

/**
 * The wiring every command shares: the project's configs as they ship, parsed once per process
 * ({@link #shipped}; a run that changes or replays them builds {@link RunConfigs} of its own), and
 * the engine the simulators run on.
 */
final class Wiring {

    private static RunConfigs shipped;
    /** The project root {@link #shipped} was read from: another root (-Dhandsim.home changed) is read afresh. */
    private static Path shippedHome;

    private Wiring() {
    }

    /** The project's model and configs as their files say, parsed once. */
    static synchronized RunConfigs shipped() {
        Path home = Home.root();
        if (shipped == null || !home.equals(shippedHome)) {
            shipped = new RunConfigs(ConfigSet.fromFiles());
            shippedHome = home;
        }
        return shipped;
    }

    /** The model of {@code file}, or the shipped one when null. */
    static HandModel model(Path file) {
        return file != null ? ModelLoader.load(file) : shipped().model();
    }

    static SimConfig simConfig() {
        return shipped().sim();
    }

    static ControllerConfig controllerConfig() {
        return shipped().controller();
    }

    static PdController pd(HandModel model) {
        return new PdController(model, controllerConfig().pd());
    }

    /** An object from {@code configs/objects/NAME.json}; an unknown name is refused in one line. */
    static ObjectSpec object(String name) {
        return shipped().object(name);
    }

    static EpisodeLimits episodeLimits() {
        return shipped().limits();
    }

    static LaunchDistribution launches() {
        return shipped().launches();
    }

    static PlannerConfig plannerConfig(String object) {
        return shipped().planner(object);
    }

    static Simulator simulator(HandModel model, SimConfig config) {
        return new OdeSimulator(model, config);
    }

    /** A twin of {@code sim} for a planner: the same model and config, on an engine of its own. */
    static Simulator twinSimulator(Simulator sim) {
        return isolatedSimulator(sim.model(), sim.config());
    }

    /** A simulator on an engine of its own (see {@link IsolatedEngine}), for several worlds in one thread. */
    static Simulator isolatedSimulator(HandModel model, SimConfig config) {
        return IsolatedEngine.simulator(model, config);
    }

    /** {@code workers} parallel rollout workers, each with an ode4j of its own (see {@link IsolatedEngine}). */
    static Rollouts<Simulator> rollouts(HandModel model, SimConfig config, int workers) {
        return new LocalRollouts<>(workers, () -> IsolatedEngine.simulator(model, config));
    }
}
