package handsim.model;

import handsim.config.Home;
import handsim.config.Json;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;

/**
 * The widest range each human joint reaches ({@code models/physiology.json}): a model's joint
 * limits must lie inside it, so a typing error (a limit of 1e6 degrees) is refused when the
 * model is loaded rather than letting the arm fold through itself. A DOF takes the range of the
 * first key that matches its name (an exact name, or a pattern with {@code *} for any text), else
 * the file's {@code default}.
 */
final class Physiology {

    /** A key of the file and the range it gives (degrees). */
    private record Entry(String key, Pattern name, double[] range) {
    }

    private final String source;
    private final double[] fallback;
    private final List<Entry> entries;

    private Physiology(String source, double[] fallback, List<Entry> entries) {
        this.source = source;
        this.fallback = fallback;
        this.entries = entries;
    }

    /** The file, under the project root. */
    static final String FILE = "models/physiology.json";

    /** The project's {@code models/physiology.json}. */
    static Physiology load() {
        return parse(Json.load(Home.resolve(FILE)));
    }

    static Physiology parse(Json j) {
        j.allow("comment");
        double[] fallback = degrees(j, "default");
        List<Entry> entries = new ArrayList<>();
        Json dofs = j.get("dofs");
        for (String key : dofs.fieldNames()) {
            Pattern name = Pattern.compile(Pattern.quote(key).replace("*", "\\E.*\\Q"));
            entries.add(new Entry(key, name, degrees(dofs, key)));
        }
        j.requireNoUnknownFields();
        return new Physiology(j.source(), fallback, entries);
    }

    /** A [low, high] range of angles within a full turn each way. */
    private static double[] degrees(Json j, String field) {
        double[] r = j.range(field);
        if (r[0] < -360 || r[1] > 360) {
            throw j.fieldError(field, "a joint range in degrees lies within [-360, 360], got [" + Json.show(r[0]) + ", "
                    + Json.show(r[1]) + "]");
        }
        return r;
    }

    /** Requires the DOF {@code dof}'s {@code range} (degrees, field {@code field} of {@code d}) inside what a human joint reaches. */
    void check(Json d, String field, String dof, double[] range) {
        String key = "default";
        double[] allowed = fallback;
        for (Entry e : entries) {
            if (e.name().matcher(dof).matches()) {
                key = e.key();
                allowed = e.range();
                break;
            }
        }
        if (range[0] < allowed[0] || range[1] > allowed[1]) {
            throw d.fieldError(field, "[" + Json.show(range[0]) + ", " + Json.show(range[1]) + "] degrees is beyond what a human "
                    + dof + " reaches, [" + Json.show(allowed[0]) + ", " + Json.show(allowed[1]) + "] (" + source + " " + key + ")");
        }
    }
}
