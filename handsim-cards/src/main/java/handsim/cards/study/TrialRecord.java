package handsim.cards.study;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.tpe.CompletedTrial;
import handsim.cards.tpe.Param;
import handsim.config.Json;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A finished trial as a study keeps it, one JSON file each: number, parameters, objective
 * values (complete) or the error (failed), the figures the objective reported, and its wall
 * time. Numbers are written in Java's shortest round-tripping form, so a trial read back is
 * bit-identical to the one written.
 *
 * @param values  objective values in config order; empty for a failed trial
 * @param error   why the trial failed; null for a complete one
 * @param seconds wall time of the objective, s
 */
public record TrialRecord(int number, double[] params, double[] values, Map<String, Double> info, String error, double seconds) {

    public TrialRecord {
        params = params.clone();
        values = values.clone();
        info = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(info));
    }

    static TrialRecord complete(int number, double[] params, Evaluation e, double seconds) {
        return new TrialRecord(number, params, e.values(), e.info(), null, seconds);
    }

    static TrialRecord failed(int number, double[] params, String error, double seconds) {
        return new TrialRecord(number, params, new double[0], Map.of(), error, seconds);
    }

    public boolean isComplete() {
        return error == null;
    }

    @Override
    public double[] params() {
        return params.clone();
    }

    @Override
    public double[] values() {
        return values.clone();
    }

    /** The parameters by name. */
    public TrialParams trialParams(StudyConfig config) {
        return TrialParams.of(number, config, params);
    }

    /** What the sampler learns from (complete trials only). */
    CompletedTrial toCompleted() {
        return new CompletedTrial(number, params, values);
    }

    ObjectNode toJson(StudyConfig config) {
        ObjectNode root = Json.mapper().createObjectNode();
        root.put("number", number);
        root.put("state", isComplete() ? "complete" : "failed");
        ObjectNode ps = root.putObject("params");
        for (int i = 0; i < params.length; i++) {
            Param p = config.params().get(i);
            if (p.integer()) {
                ps.put(p.name(), (long) params[i]);
            } else {
                ps.put(p.name(), params[i]);
            }
        }
        if (isComplete()) {
            ObjectNode vs = root.putObject("values");
            for (int i = 0; i < values.length; i++) {
                vs.put(config.objectives().get(i), values[i]);
            }
        } else {
            root.put("error", error);
        }
        ObjectNode in = root.putObject("info");
        info.forEach(in::put);
        root.put("seconds", seconds);
        return root;
    }

    static TrialRecord fromJson(Json j, StudyConfig config) {
        int number = j.integer("number", 0, Integer.MAX_VALUE);
        boolean complete = j.choice("state", "complete", "failed").equals("complete");
        Json ps = j.get("params");
        List<Param> space = config.params();
        double[] params = new double[space.size()];
        for (int i = 0; i < params.length; i++) {
            Param p = space.get(i);
            params[i] = ps.number(p.name());
            // a trial file edited by hand, or one of another study, must not steer the sampler or become the best
            if (params[i] < p.low() || params[i] > p.high() || p.integer() && params[i] != Math.rint(params[i])) {
                throw ps.fieldError(p.name(), Json.show(params[i]) + " is outside the study's search space [" + Json.show(p.low())
                        + ", " + Json.show(p.high()) + "]" + (p.integer() ? " of whole numbers" : "")
                        + " (a trial file edited by hand, or one of another study?)");
            }
        }
        ps.requireNoUnknownFields();
        double[] values = new double[0];
        String error = null;
        if (complete) {
            Json vs = j.get("values");
            values = new double[config.objectives().size()];
            for (int i = 0; i < values.length; i++) {
                values[i] = vs.number(config.objectives().get(i));
            }
            vs.requireNoUnknownFields();
        } else {
            error = j.string("error");
        }
        Map<String, Double> info = new LinkedHashMap<>();
        Json in = j.get("info");
        for (String name : in.fieldNames()) {
            info.put(name, in.number(name));
        }
        double seconds = j.number("seconds", 0, Double.MAX_VALUE);
        j.requireNoUnknownFields();
        return new TrialRecord(number, params, values, info, error, seconds);
    }
}
