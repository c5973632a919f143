package handsim.control;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.math.Vec3;
import java.util.Objects;

/**
 * How a CATCH meets the object (sec. 3.6): where its centre crosses the interception plane raised
 * by {@code planeShift}, the palm moving at {@code velocityFraction} of the object's velocity (the
 * paper's 70 %). The controller's own style is {@code (0, catch.velocityFraction)}; a task may
 * catch its thrown objects otherwise ({@link ControllerConfig#withCatchAfterThrow}), and a throw
 * planner may choose the catch of each throw with it ({@link ThrowDecision}).
 *
 * <p>With a {@link Level} search the plane moves, within its reach, to where the long axis of a
 * tumbling object is predicted to lie level, so that it lands across the palm and not on an end.
 * An {@code offset} moves where on the hand the object's centre is met, and so how it comes to
 * rest there.
 *
 * @param planeShift metres above the configured interception plane (negative: below)
 * @param velocityFraction palm velocity at interception as a fraction of the object's
 * @param level when not null, the search for a plane where the long axis lies level
 * @param offset where the object's centre is met, palm frame (m), relative to the grasp's {@code
 *     catchOffset}: a small shift changes how the object comes to rest in the hand
 */
public record CatchStyle(double planeShift, double velocityFraction, Level level, Vec3 offset) {

    /** The largest {@link #offset} a style may ask for (m): the grasp's catchOffset says where the hand meets the object. */
    public static final double MAX_OFFSET = 0.03;

    public CatchStyle {
        Objects.requireNonNull(offset, "offset (Vec3.ZERO for the grasp's own)");
    }

    /**
     * The search for a level catch: the plane is tried from {@code planeShift - below} to {@code
     * planeShift + above} in steps of {@code step} (m); the shift nearest {@code planeShift} whose
     * predicted long axis is at most {@code tilt} out of the horizontal is taken, or, when none
     * is, the one nearest to level.
     *
     * <p>With a {@code minTurn}, a plane counts as level only once the object is also predicted
     * to have turned that far end over end since it left the hand; when some plane is level but
     * none of those is turned, the nearest turned one within {@code turnTilt} of level is taken,
     * or else the most turned one within it; when no plane is level, the search is the plain one. A throw that
     * would just miss its flip on the level plane is so met lower down, after more turn.
     *
     * @param below how far the plane may move down (m): a later catch, after more turn
     * @param above how far the plane may move up (m): an earlier catch
     * @param step spacing of the tried planes (m)
     * @param tilt a long axis this far out of the horizontal (rad) counts as level
     * @param minTurn the end-over-end turn in flight (rad, {@link handsim.math.EndOverEnd#net})
     *     a plane must be predicted to come after; 0 for none
     * @param turnTilt how far out of level (rad) a plane met for its turn may be (at least {@code tilt})
     */
    public record Level(double below, double above, double step, double tilt, double minTurn, double turnTilt) {

        /** A search for a level plane alone, whatever the turn. */
        public Level(double below, double above, double step, double tilt) {
            this(below, above, step, tilt, 0, tilt);
        }

        static Level parse(Json j) {
            j.allow("comment");
            double tiltDeg = j.number("tiltDeg", 0, 90);
            if (j.has("turnTiltDeg") && !j.has("minTurnDeg")) {
                throw j.fieldError("turnTiltDeg", "goes with minTurnDeg (the turn a plane met for its turn must come after)");
            }
            double turnTiltDeg = j.has("turnTiltDeg") ? j.number("turnTiltDeg", tiltDeg, 90) : tiltDeg;
            Level l = new Level(j.number("below", 0, 0.3), j.number("above", 0, 0.3), j.number("step", 0.001, 0.3),
                    Math.toRadians(tiltDeg), Math.toRadians(j.has("minTurnDeg") ? j.number("minTurnDeg", 0, 3600) : 0),
                    Math.toRadians(turnTiltDeg));
            j.requireNoUnknownFields();
            return l;
        }

        ObjectNode toJson() {
            ObjectNode j = Json.mapper().createObjectNode().put("below", below).put("above", above).put("step", step)
                    .put("tiltDeg", Math.toDegrees(tilt));
            if (minTurn > 0) {
                j.put("minTurnDeg", Math.toDegrees(minTurn)).put("turnTiltDeg", Math.toDegrees(turnTilt));
            }
            return j;
        }
    }

    /** A style with no level search, meeting the object where the grasp says. */
    public CatchStyle(double planeShift, double velocityFraction) {
        this(planeShift, velocityFraction, null);
    }

    /** A style meeting the object where the grasp says. */
    public CatchStyle(double planeShift, double velocityFraction, Level level) {
        this(planeShift, velocityFraction, level, Vec3.ZERO);
    }

    /** This style in the file's format ({@code parse} gives it back). */
    public ObjectNode toJson() {
        ObjectNode j = Json.mapper().createObjectNode().put("planeShift", planeShift).put("velocityFraction", velocityFraction);
        if (level != null) {
            j.set("level", level.toJson());
        }
        if (offset.norm() > 0) {
            j.set("offset", Json.array(offset.toArray()));
        }
        return j;
    }

    public static CatchStyle parse(Json j) {
        j.allow("comment");
        CatchStyle s = new CatchStyle(j.number("planeShift", -0.3, 0.3), j.number("velocityFraction", 0, 1),
                j.has("level") ? Level.parse(j.get("level")) : null, j.vec3("offset", Vec3.ZERO));
        if (s.offset.norm() > MAX_OFFSET) {
            throw j.fieldError("offset", "must be within " + MAX_OFFSET + " m of the grasp's catchOffset, got " + s.offset);
        }
        j.requireNoUnknownFields();
        return s;
    }
}
