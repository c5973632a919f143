package handsim.cards.study;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/** One trial's number and parameter values by name (search-space order; integers as whole numbers). */
public record TrialParams(int number, Map<String, Double> values) {

    public TrialParams {
        values = Collections.unmodifiableMap(new LinkedHashMap<>(values));
    }

    /** Values in the config's parameter order. */
    static TrialParams of(int number, StudyConfig config, double[] values) {
        Map<String, Double> byName = new LinkedHashMap<>();
        for (int i = 0; i < values.length; i++) {
            byName.put(config.params().get(i).name(), values[i]);
        }
        return new TrialParams(number, byName);
    }

    public double get(String name) {
        Double v = values.get(name);
        if (v == null) {
            throw new IllegalArgumentException("no parameter \"" + name + "\" in this study (it has " + values.keySet() + ")");
        }
        return v;
    }

    /** An integer parameter's value. */
    public int integer(String name) {
        double v = get(name);
        if (v != Math.rint(v)) {
            throw new IllegalArgumentException("parameter \"" + name + "\" is not an integer: " + v);
        }
        return (int) v;
    }
}
