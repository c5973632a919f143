package handsim.cards.study;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * What a trial returns: its objective values and, for the record, named figures it measured
 * along the way (say the end angle, the minimum gap, Newton iterations), written into the
 * trial's file.
 */
public record Evaluation(double[] values, Map<String, Double> info) {

    public Evaluation {
        values = values.clone();
        info = Collections.unmodifiableMap(new LinkedHashMap<>(info));
        info.forEach((name, v) -> {
            if (!Double.isFinite(v)) {
                throw new IllegalArgumentException("info \"" + name + "\": must be a finite number, got " + v);
            }
        });
    }

    public static Evaluation of(double... values) {
        return new Evaluation(values, Map.of());
    }

    /** This evaluation with one more named figure. */
    public Evaluation with(String name, double value) {
        Map<String, Double> more = new LinkedHashMap<>(info);
        more.put(name, value);
        return new Evaluation(values, more);
    }

    @Override
    public double[] values() {
        return values.clone();
    }
}
