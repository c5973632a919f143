package handsim.app;

import handsim.config.Home;
import handsim.config.Json;
import handsim.control.PdController;
import handsim.control.PdGains;
import handsim.model.HandModel;
import handsim.model.ModelLoader;
import handsim.sim.ObjectSpec;
import handsim.sim.SimConfig;
import handsim.sim.Simulator;
import handsim.sim.ode.IsolatedEngine;
import handsim.sim.ode.OdeSimulator;
import handsim.rollout.LocalRollouts;
import handsim.rollout.Rollouts;
import handsim.evaluation.CatchEvaluation;
import handsim.planning.PlannerConfig;
import handsim.task.EpisodeLimits;
import handsim.kin.Kinematics;
import handsim.math.Vec3;
import handsim.task.HeightGoals;
import handsim.task.HeightTask;
import handsim.task.Tasks;
import handsim.task.ThrowTask;
import handsim.task.LaunchDistribution;
import java.nio.file.Path;

/** Loads the shipped model and configs and builds the engine: the wiring every command shares. */
final class Wiring {

    private Wiring() {
    }

    static HandModel model(Path file) {
        return ModelLoader.load(file != null ? file : Home.defaultModel());
    }

    static SimConfig simConfig() {
        return SimConfig.load(Home.resolve("configs/sim.json"));
    }

    static PdController pd(HandModel model) {
        return new PdController(model, controllerConfig().pd());
    }

    static handsim.control.ControllerConfig controllerConfig() {
        return handsim.control.ControllerConfig.load(Home.resolve("configs/controller.json"));
    }

    /** An object from {@code configs/objects/NAME.json}. */
    static ObjectSpec object(String name) {
        Path file = objectFile(name);
        if (!name.matches("[A-Za-z0-9_-]+") || !file.toFile().isFile()) {
            throw new IllegalArgumentException("unknown object \"" + name + "\" (no " + Home.root().relativize(file) + ")");
        }
        return ObjectSpec.load(file);
    }

    /** Where the object {@code name} is described: {@code configs/objects/NAME.json}. */
    private static Path objectFile(String name) {
        return Home.resolve("configs/objects/" + name + ".json");
    }

    /** Seeded catch-and-throw episodes of the nominal controller on {@code task} with the shipped launch and episode configs. */
    static CatchEvaluation nominalEvaluation(String object, ThrowTask task) {
        return CatchEvaluation.nominal(controllerConfig(), episodeLimits(), launches(), object(object), task);
    }

    static EpisodeLimits episodeLimits() {
        return EpisodeLimits.parse(Json.load(Home.resolve("configs/episode.json")));
    }

    static LaunchDistribution launches() {
        return LaunchDistribution.load(Home.resolve("configs/launch.json"));
    }

    /** The palm centre in the model's neutral pose (m, world): where tasks measure their goals from. */
    static Vec3 neutralPalm(HandModel model) {
        return new Kinematics(model).siteFrame(model.site("palm_center"), model.poseVector("neutral")).origin();
    }

    /** The shipped tasks (configs/tasks). */
    static Tasks tasks() {
        return new Tasks(controllerConfig().nominalThrows(), neutralPalm(model(null)), simConfig().groundHeight());
    }

    /** The height task of {@code configs/tasks/height.json} aiming at {@code goals}. */
    static HeightTask heightTask(HeightGoals goals) {
        return tasks().height(goals);
    }

    static Simulator simulator(HandModel model, SimConfig config) {
        return new OdeSimulator(model, config);
    }

    /**
     * {@code configs/planner.json}, with {@code object}'s own settings if it has some; an entry
     * under {@code objects} for an object that {@code configs/objects/} lacks is refused by name.
     */
    static PlannerConfig plannerConfig(String object) {
        Json file = Json.load(Home.resolve("configs/planner.json"));
        if (file.has("objects")) {
            Json objects = file.get("objects");
            for (String name : objects.fieldNames()) {
                Path described = objectFile(name);
                if (!described.toFile().isFile()) {
                    throw objects.fieldError(name, "no such object (no " + Home.root().relativize(described) + ")");
                }
            }
        }
        return PlannerConfig.parse(file, object);
    }

    /** A twin of {@code sim} for a planner: the same model and config, on an engine of its own. */
    static Simulator twinSimulator(Simulator sim) {
        return IsolatedEngine.simulator(sim.model(), sim.config());
    }

    /** {@code workers} parallel rollout workers, each with an ode4j of its own (see {@link IsolatedEngine}). */
    static Rollouts<Simulator> rollouts(HandModel model, SimConfig config, int workers) {
        return new LocalRollouts<>(workers, () -> IsolatedEngine.simulator(model, config));
    }
}
