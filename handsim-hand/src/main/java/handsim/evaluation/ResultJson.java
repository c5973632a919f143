package handsim.evaluation;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.control.ThrowParameters;
import handsim.math.Vec3;
import handsim.planning.ThrowPlanner;
import handsim.task.CatchThrowEpisode;
import handsim.task.EpisodeResult;
import handsim.task.LoopRecord;
import java.util.ArrayList;
import java.util.List;

/**
 * Evaluation results as JSON and back, exactly: every double is written in its shortest form
 * that reads back to the same bits, NaN as null (JSON has no NaN). What an evaluation's episode
 * journal holds ({@link handsim.evaluation.EpisodeJournal}).
 */
public final class ResultJson {

    private static final JsonNodeFactory F = JsonNodeFactory.instance;

    private ResultJson() {
    }

    public static ObjectNode loop(LoopRecord r) {
        ObjectNode o = F.objectNode();
        o.put("index", r.index());
        o.put("caught", r.caught());
        number(o, "apex", r.apexHeight());
        o.set("landing", vec(r.landing()));
        number(o, "target", r.targetHeight());
        o.set("throw", r.throwParams() == null ? F.nullNode() : array(r.throwParams().toArray()));
        o.put("box_hit", r.boxHit());
        number(o, "box_distance", r.boxDistance());
        number(o, "flight_rotation", r.flightRotation());
        number(o, "release_spin", r.releaseSpin());
        number(o, "catch_tilt", r.catchTilt());
        number(o, "catch_heading", r.catchHeading());
        o.set("catch_point", vec(r.catchPoint()));
        number(o, "arrival_tilt", r.arrivalTilt());
        number(o, "max_penetration", r.maxPenetration());
        number(o, "max_limit_excess", r.maxLimitExcess());
        number(o, "peak_torque_ratio", r.peakTorqueRatio());
        number(o, "duration", r.duration());
        return o;
    }

    public static LoopRecord loop(JsonNode o) {
        JsonNode t = o.get("throw");
        return new LoopRecord(o.get("index").asInt(), o.get("caught").asBoolean(), number(o, "apex"), vec(o.get("landing")),
                number(o, "target"), t.isNull() ? null : ThrowParameters.fromArray(numbers(t)), o.get("box_hit").asBoolean(),
                number(o, "box_distance"), number(o, "flight_rotation"), number(o, "release_spin"), number(o, "catch_tilt"),
                number(o, "catch_heading"),
                vec(o.get("catch_point")), number(o, "arrival_tilt"), number(o, "max_penetration"), number(o, "max_limit_excess"),
                number(o, "peak_torque_ratio"), number(o, "duration"));
    }

    public static ArrayNode loops(List<LoopRecord> loops) {
        ArrayNode a = F.arrayNode();
        loops.forEach(r -> a.add(loop(r)));
        return a;
    }

    public static List<LoopRecord> loops(JsonNode a) {
        List<LoopRecord> out = new ArrayList<>();
        a.forEach(o -> out.add(loop(o)));
        return out;
    }

    public static ObjectNode episode(EpisodeResult r) {
        ObjectNode o = F.objectNode();
        o.put("seed", r.seed());
        o.put("status", r.status().name());
        o.set("loops", loops(r.loops()));
        return o;
    }

    public static EpisodeResult episode(JsonNode o) {
        return new EpisodeResult(o.get("seed").asLong(), loops(o.get("loops")), CatchThrowEpisode.Status.valueOf(o.get("status").asText()));
    }

    public static ObjectNode boxTrial(BoxTrials.Trial t) {
        ObjectNode o = F.objectNode();
        o.put("index", t.index());
        o.put("seed", t.seed());
        o.set("box", vec(t.box()));
        number(o, "distance", t.distance());
        o.put("success", t.success());
        o.put("in_a_row", t.inARow());
        number(o, "max_limit_excess", t.motion().maxLimitExcess());
        number(o, "max_penetration", t.motion().maxPenetration());
        number(o, "peak_torque_ratio", t.motion().peakTorqueRatio());
        return o;
    }

    public static BoxTrials.Trial boxTrial(JsonNode o) {
        return new BoxTrials.Trial(o.get("index").asInt(), o.get("seed").asLong(), vec(o.get("box")), number(o, "distance"),
                o.get("success").asBoolean(), o.get("in_a_row").asInt(), new MotionQuality(number(o, "max_limit_excess"),
                        number(o, "max_penetration"), number(o, "peak_torque_ratio")));
    }

    public static ObjectNode plannerStats(ThrowPlanner.Stats s) {
        ObjectNode o = F.objectNode();
        o.put("decisions", s.decisions());
        o.put("tries", s.tries());
        o.put("unsolved", s.unsolved());
        o.put("mispredicted", s.mispredicted());
        o.put("promised", s.promised());
        o.put("restyled_catches", s.restyledCatches());
        o.put("restyled_throw_ins", s.restyledThrowIns());
        o.put("branches", s.branches());
        return o;
    }

    public static ThrowPlanner.Stats plannerStats(JsonNode o) {
        return new ThrowPlanner.Stats(o.get("decisions").asInt(), o.get("tries").asInt(), o.get("unsolved").asInt(),
                o.get("mispredicted").asInt(), o.get("promised").asInt(), o.get("restyled_catches").asInt(),
                o.get("restyled_throw_ins").asInt(), o.get("branches").asInt());
    }

    /** A number, NaN as null and an infinity as the string "Infinity" or "-Infinity" (JSON has neither). */
    private static void number(ObjectNode o, String key, double v) {
        if (Double.isNaN(v)) {
            o.putNull(key);
        } else if (Double.isInfinite(v)) {
            o.put(key, Double.toString(v));
        } else {
            o.put(key, v);
        }
    }

    private static double number(JsonNode o, String key) {
        JsonNode v = o.get(key);
        return v == null || v.isNull() ? Double.NaN : v.isTextual() ? Double.parseDouble(v.asText()) : v.asDouble();
    }

    /** A point as a JSON array [x, y, z] (null for none). */
    static JsonNode vec(Vec3 v) {
        return v == null ? F.nullNode() : array(v.x(), v.y(), v.z());
    }

    private static Vec3 vec(JsonNode a) {
        if (a == null || a.isNull()) {
            return null;
        }
        double[] v = numbers(a);
        return new Vec3(v[0], v[1], v[2]);
    }

    private static ArrayNode array(double... values) {
        ArrayNode a = F.arrayNode();
        for (double v : values) {
            a.add(v);
        }
        return a;
    }

    private static double[] numbers(JsonNode a) {
        double[] v = new double[a.size()];
        for (int i = 0; i < v.length; i++) {
            v[i] = a.get(i).asDouble();
        }
        return v;
    }
}
