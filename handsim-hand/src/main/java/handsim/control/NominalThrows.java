package handsim.control;

import handsim.config.Json;
import handsim.math.Vec3;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * Hand-tuned throw parameters per desired apex height (the paper tunes the nominal controller
 * for every height, sec. 4.2); heights between entries are interpolated linearly, heights
 * outside use the nearest entry.
 */
public record NominalThrows(List<Entry> entries) {

    /** Parameters that throw the object to {@code apexHeight} (m, world). */
    public record Entry(double apexHeight, ThrowParameters params) {
    }

    public NominalThrows {
        entries = entries.stream().sorted(Comparator.comparingDouble(Entry::apexHeight)).toList();
        if (entries.isEmpty()) {
            throw new IllegalArgumentException("at least one nominal throw is needed");
        }
    }

    public static NominalThrows parse(Json j) {
        List<Entry> out = new ArrayList<>();
        for (Json e : j.elements()) {
            e.allow("comment");
            Vec3 rDeg = e.vec3("rTargetDeg");
            out.add(new Entry(e.number("apexHeight"), new ThrowParameters(e.vec3("dOffset"),
                    rDeg.times(Math.PI / 180), e.number("tOpen", 0, 10))));
            e.requireNoUnknownFields();
        }
        if (out.isEmpty()) {
            throw j.error("at least one nominal throw is needed");
        }
        return new NominalThrows(out);
    }

    public ThrowParameters forHeight(double apex) {
        Entry first = entries.get(0), last = entries.get(entries.size() - 1);
        if (apex <= first.apexHeight()) {
            return first.params();
        }
        if (apex >= last.apexHeight()) {
            return last.params();
        }
        for (int i = 1; i < entries.size(); i++) {
            Entry a = entries.get(i - 1), b = entries.get(i);
            if (apex <= b.apexHeight()) {
                return a.params().lerp(b.params(), (apex - a.apexHeight()) / (b.apexHeight() - a.apexHeight()));
            }
        }
        return last.params();
    }

    /** Lowest and highest tuned apex heights. */
    public double minHeight() {
        return entries.get(0).apexHeight();
    }

    public double maxHeight() {
        return entries.get(entries.size() - 1).apexHeight();
    }
}
