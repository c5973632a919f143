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
import handsim.sim.ode.OdeSimulator;
import java.nio.file.Path;

/** Loads the shipped model and configs and builds the engine: the wiring every command shares. */
final class Runtime {

    private Runtime() {
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
        Path file = Home.resolve("configs/objects/" + name + ".json");
        if (!file.toFile().isFile()) {
            throw new IllegalArgumentException("unknown object \"" + name + "\" (no " + Home.root().relativize(file) + ")");
        }
        return ObjectSpec.load(file);
    }

    static Simulator simulator(HandModel model, SimConfig config) {
        return new OdeSimulator(model, config);
    }
}
