package handsim.cards.sleight;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The decision variables of Card Snapping (thesis 4.2.4): the bones pinch in [t0, t1] (s) at
 * mean speed vp (m/s), then slide in [t2, t3] at mean speed vs (m/s).
 */
public record SnapParams(double t0, double t1, double vp, double t2, double t3, double vs) {

    /** The fastest mean bone speed of a trial (m/s), {@link BoneWindows#MAX_SPEED}. */
    public static final double MAX_SPEED = BoneWindows.MAX_SPEED;

    /** Reads {@code {"t0": …, "t1": …, "vp": …, "t2": …, "t3": …, "vs": …}} (a "comment" is allowed). */
    public static SnapParams parse(Json j) {
        j.allow("comment");
        SnapParams p = of(BoneWindows.parse(j));
        j.requireNoUnknownFields();
        p.validate(Double.POSITIVE_INFINITY, j.source());
        return p;
    }

    static SnapParams of(BoneWindows w) {
        return new SnapParams(w.t0(), w.t1(), w.vp(), w.t2(), w.t3(), w.vs());
    }

    /** The pinch and the slide as motion windows. */
    public BoneWindows windows() {
        return new BoneWindows(t0, t1, vp, t2, t3, vs);
    }

    /**
     * Requires 0 ≤ t0 < t1 ≤ t2 < t3 ≤ duration and speeds in [0, {@link #MAX_SPEED}]; the
     * message names the offending field and value.
     */
    public void validate(double duration, String source) {
        windows().validate(duration, source);
    }

    /** As a JSON object. */
    public ObjectNode toJson() {
        ObjectNode o = Json.mapper().createObjectNode();
        byName().forEach(o::put);
        return o;
    }

    /** The parameters by name, as a study has them. */
    public Map<String, Double> byName() {
        Map<String, Double> m = new LinkedHashMap<>();
        windows().putInto(m);
        return m;
    }
}
