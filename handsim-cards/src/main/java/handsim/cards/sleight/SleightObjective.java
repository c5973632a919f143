package handsim.cards.sleight;

import handsim.cards.study.Objective;
import handsim.cards.study.PortableObjective;
import handsim.config.Json;

/**
 * A card sleight as a study's objective in the form that travels to a cluster: what the trial
 * was built from ({@link CardSleight#inputs}: the sleight, fingertip mesh and card preset, its
 * configs as read with their overrides, and the budget), as JSON text. An executor builds the
 * sleight from it alone, reading no file, and makes the start state (Card Snapping's hold,
 * Double Lift's rested stack) once for all the trials it runs.
 *
 * @param inputs {@link CardSleight#inputs} of the driver's sleight, as JSON text
 */
public record SleightObjective(String inputs) implements PortableObjective {

    private static final long serialVersionUID = 1L;

    public static SleightObjective of(CardSleight sleight) {
        return new SleightObjective(sleight.inputs().toString());
    }

    @Override
    public Objective build() {
        return Sleights.fromInputs(Json.parse("the sleight's inputs", inputs).node(), null, null).objective();
    }
}
