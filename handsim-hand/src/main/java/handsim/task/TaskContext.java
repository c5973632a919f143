package handsim.task;

import handsim.control.NominalThrows;
import handsim.math.Vec3;

/**
 * What every task is measured from, fixed by the model and the controller: the hand-tuned throws
 * per apex height (configs/controller.json), the palm centre in the neutral pose, where goals are
 * placed from (m, world), and the height of the ground plane (m).
 */
public record TaskContext(NominalThrows nominal, Vec3 neutralPalm, double groundHeight) {
}
