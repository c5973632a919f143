package handsim.control;

import handsim.config.Json;

/**
 * Damped least squares IK settings (eq. 2).
 *
 * @param damping lambda of eq. (2)
 * @param positionWeight weight of the palm position error rows (1/m)
 * @param orientationWeight weight of the palm orientation error rows (1/rad); the paper weights
 *     position and orientation differently "for better catching"
 * @param iterations DLS iterations per controller tick, warm-started from the last solution
 * @param maxPositionStep largest position error (m) one iteration tries to remove
 * @param maxRotationStep largest orientation error (rad) one iteration tries to remove
 */
public record IkConfig(double damping, double positionWeight, double orientationWeight, int iterations,
        double maxPositionStep, double maxRotationStep) {

    public static IkConfig parse(Json j) {
        j.allow("comment");
        IkConfig c = new IkConfig(j.number("damping", 1e-6, 10), j.number("positionWeight", 0, 1e6),
                j.number("orientationWeight", 0, 1e6), j.integer("iterations", 1, 1000), j.positive("maxPositionStep"),
                j.positive("maxRotationStep"));
        j.requireNoUnknownFields();
        return c;
    }
}
