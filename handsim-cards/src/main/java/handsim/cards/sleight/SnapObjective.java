package handsim.cards.sleight;

import handsim.cards.sim.CardsConfig;
import handsim.cards.study.Objective;
import handsim.cards.study.PortableObjective;
import handsim.config.Json;

/**
 * Card Snapping as a study's objective in the form that travels to a cluster: the trial's
 * configuration documents as read ({@link SnapTrial#inputs}: snap.json with its overrides,
 * materials.json, solver.json, the fingertip mesh and card preset), as JSON text. An executor
 * builds the trial from them alone, reading no file, and simulates its hold once for all the
 * trials it runs.
 *
 * @param inputs {@link SnapTrial#inputs} of the driver's trial, as JSON text
 */
public record SnapObjective(String inputs) implements PortableObjective {

    private static final long serialVersionUID = 1L;

    public static SnapObjective of(SnapTrial trial) {
        return new SnapObjective(trial.inputs().toString());
    }

    @Override
    public Objective build() {
        Json in = Json.parse("Card Snapping inputs", inputs);
        SnapConfig config = SnapConfig.parse(in.get("snap"), in.string("mesh"));
        CardsConfig.Materials materials = CardsConfig.materials(in.get("materials"), in.string("card"));
        return SnapStudy.objective(new SnapTrial(config, materials, CardsConfig.solver(in.get("solver"))));
    }
}
