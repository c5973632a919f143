package handsim.cards.sleight;

import handsim.config.Json;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The decision variables of Double Lift (thesis 4.2.5): the fingers' start height hStart (m, the
 * fingertips' centres above the top of the rested stack), a pinch in [t0, t1] (s) at mean speed
 * vp (m/s) towards the stack, and a lift in [t2, t3] at mean speed vs (m/s) upwards.
 */
public record LiftParams(double hStart, BoneWindows windows) {

    /** Reads {@code {"hStart": …, "t0": …, …, "vs": …}} (a "comment" is allowed). */
    public static LiftParams parse(Json j) {
        j.allow("comment");
        LiftParams p = new LiftParams(j.number("hStart"), BoneWindows.parse(j));
        j.requireNoUnknownFields();
        return p;
    }

    static LiftParams of(Map<String, Double> p) {
        return new LiftParams(BoneWindows.get(p, "hStart"), BoneWindows.of(p));
    }

    /**
     * The farthest the fingertips' centres may start from the top of the stack (m), above or
     * below: 2 cm, beyond the fingertip's own half-height (7.5 mm) and the stack's height
     * (54 cards of 0.26 mm, 14 mm), so a finger placed there touches no card it could lift.
     */
    public static final double MAX_START_HEIGHT = 0.02;

    /**
     * Requires |hStart| ≤ {@link #MAX_START_HEIGHT} and windows 0 ≤ t0 < t1 ≤ t2 < t3 ≤
     * {@code lastLiftEnd}, speeds in [0, {@link BoneWindows#MAX_SPEED}]; the message names the
     * field and value.
     */
    public void validate(double lastLiftEnd, String source) {
        if (!(Math.abs(hStart) <= MAX_START_HEIGHT)) {
            throw new IllegalArgumentException((source == null ? "" : source + ": ") + "hStart must be a height in [-"
                    + Json.show(MAX_START_HEIGHT) + ", " + Json.show(MAX_START_HEIGHT) + "] m, got " + Json.show(hStart));
        }
        windows.validate(lastLiftEnd, source);
    }

    /** The parameters by name, as a study has them. */
    public Map<String, Double> byName() {
        Map<String, Double> m = new LinkedHashMap<>();
        m.put("hStart", hStart);
        windows.putInto(m);
        return m;
    }
}
