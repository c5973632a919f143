package handsim.app;

import handsim.config.Json;
import handsim.model.ModelLoader;
import handsim.rollout.PortableResource;
import handsim.sim.SimConfig;
import handsim.sim.Simulator;
import handsim.sim.ode.IsolatedEngine;
import handsim.spec.RunConfigs;

/**
 * A rollout worker's simulator in the form that travels to a cluster: the model, the physiology
 * the model is checked against and the physics configuration as the run read them (JSON text); an
 * executor builds the simulator from them alone, on an ode4j engine of its own ({@link
 * IsolatedEngine}), as the thread pool's workers do.
 *
 * @param model {@code models/arm_hand.json} as read
 * @param physiology {@code models/physiology.json} as read
 * @param sim {@code configs/sim.json} as read
 */
record PortableSimulator(String model, String physiology, String sim) implements PortableResource<Simulator> {

    private static final long serialVersionUID = 1L;

    /** The simulator of {@code configs}' model and physics. */
    static PortableSimulator of(RunConfigs configs) {
        return new PortableSimulator(configs.files().get(RunConfigs.MODEL).node().toString(), configs.physiology(),
                configs.files().get(RunConfigs.SIM).node().toString());
    }

    @Override
    public Simulator create() {
        return IsolatedEngine.simulator(ModelLoader.parse(Json.parse(RunConfigs.MODEL, model), physiology), SimConfig.parse(Json.parse(RunConfigs.SIM, sim)));
    }
}
