package handsim.scene;

import handsim.sim.Simulator;
import handsim.sim.WorldSnapshot;
import handsim.task.HeldBallScenario;
import java.util.LinkedHashMap;
import java.util.Map;

/** The foundation's {@link HeldBallScenario} as a scene to look at: a ball thrown into the palm and held. */
public final class HeldBallScene implements Scene {

    private final Simulator sim;
    private final HeldBallScenario scenario;

    /** Owns {@code loop}'s simulator (closed with the scene). */
    public HeldBallScene(HeldBallScenario scenario) {
        this.scenario = scenario;
        this.sim = scenario.loop().sim();
    }

    @Override
    public void advance(double seconds) {
        double until = sim.time() + seconds;
        while (sim.time() < until - 1e-12) {
            scenario.step();
        }
    }

    @Override
    public double time() {
        return sim.time();
    }

    @Override
    public WorldSnapshot snapshot() {
        return sim.snapshot();
    }

    @Override
    public Map<String, String> status() {
        Map<String, String> s = new LinkedHashMap<>();
        s.put("scene", "held ball");
        s.put("ball", Double.isNaN(scenario.contactTime()) ? "in flight" : sim.handContacts().any() ? "in the hand" : "loose");
        s.put("t", String.format("%.2f s", sim.time()));
        return s;
    }

    @Override
    public void close() {
        sim.close();
    }
}
