package handsim.control;

import handsim.config.Json;

/**
 * How a CATCH meets the object (sec. 3.6): where its centre crosses the interception plane raised
 * by {@code planeShift}, the palm moving at {@code velocityFraction} of the object's velocity (the
 * paper's 70 %). The controller's own style is {@code (0, catch.velocityFraction)}; a task may
 * catch its thrown objects otherwise ({@link ControllerConfig#withCatchAfterThrow}), and a throw
 * planner may choose the catch of each throw with it ({@link ThrowDecision}).
 *
 * @param planeShift metres above the configured interception plane (negative: below)
 * @param velocityFraction palm velocity at interception as a fraction of the object's
 */
public record CatchStyle(double planeShift, double velocityFraction) {

    public static CatchStyle parse(Json j) {
        j.allow("comment");
        CatchStyle s = new CatchStyle(j.number("planeShift", -0.3, 0.3), j.number("velocityFraction", 0, 1));
        j.requireNoUnknownFields();
        return s;
    }
}
