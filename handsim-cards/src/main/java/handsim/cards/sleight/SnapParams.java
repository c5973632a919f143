package handsim.cards.sleight;

import handsim.config.Json;

/**
 * The decision variables of Card Snapping (thesis 4.2.4): the bones pinch in [t0, t1] (s) at
 * mean speed vp (m/s), then slide in [t2, t3] at mean speed vs (m/s).
 */
public record SnapParams(double t0, double t1, double vp, double t2, double t3, double vs) {

    /**
     * The fastest mean bone speed of a trial (m/s): a fingertip flicked as fast as a hand can
     * moves at about 2 m/s, and even that crosses the card's width (63.5 mm) in 0.03 s, three
     * time steps; the searched pinches and slides stay below 0.012 m/s.
     */
    public static final double MAX_SPEED = 2;

    /** Reads {@code {"t0": …, "t1": …, "vp": …, "t2": …, "t3": …, "vs": …}} (a "comment" is allowed). */
    public static SnapParams parse(Json j) {
        j.allow("comment");
        SnapParams p = new SnapParams(j.number("t0"), j.number("t1"), j.number("vp"), j.number("t2"), j.number("t3"), j.number("vs"));
        j.requireNoUnknownFields();
        p.validate(Double.POSITIVE_INFINITY, j.source());
        return p;
    }

    /**
     * Requires 0 ≤ t0 < t1 ≤ t2 < t3 ≤ duration and speeds in [0, {@link #MAX_SPEED}]; the
     * message names the offending field and value.
     */
    public void validate(double duration, String source) {
        String where = source == null ? "" : source + ": ";
        check(t0 >= 0, where + "t0 must be >= 0, got " + t0);
        check(t1 > t0, where + "t1 must be > t0 = " + t0 + ", got " + t1);
        check(t2 >= t1, where + "t2 must be >= t1 = " + t1 + ", got " + t2);
        check(t3 > t2, where + "t3 must be > t2 = " + t2 + ", got " + t3);
        check(t3 <= duration, where + "t3 must be <= the trial duration " + duration + ", got " + t3);
        check(vp >= 0 && vp <= MAX_SPEED, where + "vp must be a speed in [0, " + Json.show(MAX_SPEED) + "] m/s, got " + Json.show(vp));
        check(vs >= 0 && vs <= MAX_SPEED, where + "vs must be a speed in [0, " + Json.show(MAX_SPEED) + "] m/s, got " + Json.show(vs));
    }

    private static void check(boolean ok, String message) {
        if (!ok) {
            throw new IllegalArgumentException(message);
        }
    }

    /** As a JSON object. */
    public com.fasterxml.jackson.databind.node.ObjectNode toJson() {
        com.fasterxml.jackson.databind.node.ObjectNode o = Json.mapper().createObjectNode();
        o.put("t0", t0);
        o.put("t1", t1);
        o.put("vp", vp);
        o.put("t2", t2);
        o.put("t3", t3);
        o.put("vs", vs);
        return o;
    }
}
