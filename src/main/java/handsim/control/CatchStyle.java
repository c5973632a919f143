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
     * @param below how far the plane may move down (m): a later catch, after more turn
     * @param above how far the plane may move up (m): an earlier catch
     * @param step spacing of the tried planes (m)
     * @param tilt a long axis this far out of the horizontal (rad) counts as level
     */
    public record Level(double below, double above, double step, double tilt) {

        static Level parse(Json j) {
            j.allow("comment");
            Level l = new Level(j.number("below", 0, 0.3), j.number("above", 0, 0.3), j.number("step", 0.001, 0.3),
                    Math.toRadians(j.number("tiltDeg", 0, 90)));
            j.requireNoUnknownFields();
            return l;
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
            j.putObject("level").put("below", level.below()).put("above", level.above()).put("step", level.step())
                    .put("tiltDeg", Math.toDegrees(level.tilt()));
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
