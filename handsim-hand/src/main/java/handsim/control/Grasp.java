package handsim.control;

import handsim.config.Json;
import handsim.math.Vec3;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * How the hand receives and holds one kind of object: the model poses used as "open" and
 * "closed" (sec. 3.5; the paper tunes the poses per object, sec. 5) and where on the hand the
 * object is met. The object's centre is planned to arrive at {@code (0, -halfThickness, 0) +
 * catchOffset} in the palm frame (x distal, y the back of the hand, z toward the little
 * finger): one half-thickness off the palm, moved by the offset.
 *
 * @param openPose model pose the fingers take during CATCH, before the first contact
 * @param closedPose model pose the fingers close to at the first contact, drawn tighter than
 *     the object so the grasp squeezes (sec. 3.4)
 * @param catchOffset where the object's centre is met, relative to one half-thickness above
 *     the palm centre, palm frame (m)
 */
public record Grasp(String openPose, String closedPose, Vec3 catchOffset) {

    static Grasp parse(Json j) {
        j.allow("comment");
        Grasp g = new Grasp(j.string("openPose"), j.string("closedPose"), j.vec3("catchOffset"));
        if (g.catchOffset.norm() > 0.1) {
            throw j.fieldError("catchOffset", "must be within 0.1 m of the palm centre, got " + g.catchOffset);
        }
        j.requireNoUnknownFields();
        return g;
    }

    /** The object's centre at the catch, palm frame, for an object of the given half-thickness (m). */
    public Vec3 objectInPalm(double halfThickness) {
        return new Vec3(0, -halfThickness, 0).plus(catchOffset);
    }

    /**
     * The grasps of every object by name, with a required {@code default} for objects not
     * listed ({@code "grasps"} in {@code configs/controller.json}).
     */
    public record Table(Map<String, Grasp> byObject) {

        public static final String DEFAULT = "default";

        public Table {
            byObject = Map.copyOf(byObject);
        }

        static Table parse(Json j) {
            j.allow("comment");
            Map<String, Grasp> grasps = new LinkedHashMap<>();
            for (String name : j.fieldNames()) {
                if (!name.equals("comment")) {
                    grasps.put(name, Grasp.parse(j.get(name)));
                }
            }
            if (!grasps.containsKey(DEFAULT)) {
                throw j.fieldError(DEFAULT, "a default grasp is required");
            }
            return new Table(grasps);
        }

        /** The grasp of the object named {@code object}, or the default one. */
        public Grasp forObject(String object) {
            return byObject.getOrDefault(object, byObject.get(DEFAULT));
        }
    }
}
