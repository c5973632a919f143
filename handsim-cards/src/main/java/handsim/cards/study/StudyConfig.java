package handsim.cards.study;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.tpe.Direction;
import handsim.cards.tpe.Param;
import handsim.cards.tpe.TpeSettings;
import handsim.config.Json;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;

/**
 * What a study searches: its objectives (names and directions), its parameters (name, low,
 * high, log, int), the TPE sampler's settings and how many trials may run at once. Read from
 * JSON:
 * <pre>
 * {
 *   "objectives": [{"name": "regret", "direction": "minimize", "tolerance": 0.01}],
 *   "params": [{"name": "x", "low": -5.0, "high": 10.0},
 *              {"name": "rate", "low": 0.001, "high": 0.1, "log": true},
 *              {"name": "k", "low": 1, "high": 4, "int": true}],
 *   "parallelTrials": 2,
 *   "sampler": {"nStartupTrials": 10}
 * }
 * </pre>
 * {@code log} and {@code int} default to false; every {@code sampler} field defaults to Optuna
 * 3.6.1's ({@link TpeSettings#OPTUNA_DEFAULTS}; {@code "multivariate": true} selects multivariate
 * TPE). An objective's optional {@code tolerance} (> 0, minimised objectives only) is the
 * value it must not exceed for a trial to meet the sleight: the chosen trial of a study is the
 * complete one closest to zero with each objective scaled by its tolerance. {@code parallelTrials} is part of the search,
 * not of the machine: trial k is suggested from trials 0 … k - parallelTrials (see
 * {@link Study}), so at most that many trials run at once whatever the number of workers.
 * {@code comment} fields are allowed everywhere.
 */
public record StudyConfig(List<String> objectives, List<Direction> directions, List<Double> tolerances, List<Param> params, TpeSettings sampler,
                          int parallelTrials) {

    public StudyConfig {
        objectives = List.copyOf(objectives);
        directions = List.copyOf(directions);
        tolerances = List.copyOf(tolerances);
        if (tolerances.size() != objectives.size()) {
            throw new IllegalArgumentException("objectives: " + objectives.size() + " objectives but " + tolerances.size() + " tolerances");
        }
        params = List.copyOf(params);
        if (objectives.isEmpty() || objectives.size() != directions.size()) {
            throw new IllegalArgumentException("objectives: need one or more, each with a direction; got " + objectives + " and " + directions);
        }
        if (params.isEmpty()) {
            throw new IllegalArgumentException("params: the search space has no parameters");
        }
        if (parallelTrials < 1) {
            throw new IllegalArgumentException("parallelTrials: must be >= 1, got " + parallelTrials);
        }
    }

    public static StudyConfig load(Path file) {
        return parse(Json.load(file));
    }

    /** Parses and validates; errors name the source, the field and the bad value. */
    public static StudyConfig parse(Json root) {
        root.allow("comment");
        List<String> names = new ArrayList<>();
        List<Direction> directions = new ArrayList<>();
        List<Double> tolerances = new ArrayList<>();
        Set<String> seen = new HashSet<>();
        List<Json> objectives = root.array("objectives");
        if (objectives.isEmpty()) {
            throw root.fieldError("objectives", "needs at least one objective");
        }
        for (Json o : objectives) {
            o.allow("comment");
            String name = o.string("name");
            if (!seen.add(name)) {
                throw o.fieldError("name", "objective \"" + name + "\" appears twice");
            }
            names.add(name);
            Direction direction = Direction.valueOf(o.choice("direction", "minimize", "maximize").toUpperCase(Locale.ROOT));
            directions.add(direction);
            if (o.has("tolerance")) {
                if (direction != Direction.MINIMIZE) {
                    throw o.fieldError("tolerance", "only a minimised objective has a tolerance");
                }
                tolerances.add(o.positive("tolerance"));
            } else {
                tolerances.add(Double.NaN);
            }
            o.requireNoUnknownFields();
        }
        List<Param> params = new ArrayList<>();
        seen.clear();
        List<Json> paramNodes = root.array("params");
        if (paramNodes.isEmpty()) {
            throw root.fieldError("params", "the search space needs at least one parameter");
        }
        for (Json p : paramNodes) {
            p.allow("comment");
            String name = p.string("name");
            if (!seen.add(name)) {
                throw p.fieldError("name", "parameter \"" + name + "\" appears twice");
            }
            double low = p.number("low"), high = p.number("high");
            boolean log = p.bool("log", false), integer = p.bool("int", false);
            p.requireNoUnknownFields();
            try {
                params.add(new Param(name, low, high, log, integer));
            } catch (IllegalArgumentException e) {
                throw p.error(e.getMessage());
            }
        }
        int parallelTrials = root.integer("parallelTrials", 1, 1024);
        TpeSettings sampler = TpeSettings.OPTUNA_DEFAULTS;
        if (root.has("sampler")) {
            Json s = root.get("sampler");
            s.allow("comment");
            TpeSettings d = TpeSettings.OPTUNA_DEFAULTS;
            int nStartup = s.has("nStartupTrials") ? s.integer("nStartupTrials", 0, 1_000_000) : d.nStartupTrials();
            int nCandidates = s.has("nEiCandidates") ? s.integer("nEiCandidates", 1, 1_000_000) : d.nEiCandidates();
            double priorWeight = s.has("priorWeight") ? s.positive("priorWeight") : d.priorWeight();
            sampler = new TpeSettings(nStartup, nCandidates, s.bool("considerPrior", d.considerPrior()), priorWeight,
                    s.bool("considerMagicClip", d.considerMagicClip()), s.bool("considerEndpoints", d.considerEndpoints()),
                    s.bool("multivariate", d.multivariate()));
            s.requireNoUnknownFields();
        }
        root.requireNoUnknownFields();
        return new StudyConfig(names, directions, tolerances, params, sampler, parallelTrials);
    }

    /** The config as JSON, every default spelt out (what study.json records). */
    public ObjectNode toJson() {
        ObjectNode root = Json.mapper().createObjectNode();
        ArrayNode objs = root.putArray("objectives");
        for (int i = 0; i < objectives.size(); i++) {
            ObjectNode o = objs.addObject().put("name", objectives.get(i)).put("direction", directions.get(i).name().toLowerCase(Locale.ROOT));
            if (hasTolerance(i)) {
                o.put("tolerance", tolerances.get(i));
            }
        }
        ArrayNode ps = root.putArray("params");
        for (Param p : params) {
            ps.addObject().put("name", p.name()).put("low", p.low()).put("high", p.high()).put("log", p.log()).put("int", p.integer());
        }
        root.put("parallelTrials", parallelTrials);
        ObjectNode s = root.putObject("sampler");
        s.put("nStartupTrials", sampler.nStartupTrials()).put("nEiCandidates", sampler.nEiCandidates())
                .put("considerPrior", sampler.considerPrior()).put("priorWeight", sampler.priorWeight())
                .put("considerMagicClip", sampler.considerMagicClip()).put("considerEndpoints", sampler.considerEndpoints());
        if (sampler.multivariate()) {
            s.put("multivariate", true); // written only when set, so the records of independent studies stay as they were
        }
        return root;
    }

    /** The config written by {@link #toJson()}, read back. */
    static StudyConfig fromJson(String source, JsonNode node) {
        return parse(Json.of(source, node));
    }

    public boolean multiObjective() {
        return objectives.size() > 1;
    }

    public boolean hasTolerance(int objective) {
        return !Double.isNaN(tolerances.get(objective));
    }

    /** Whether every objective has a tolerance. */
    public boolean hasTolerances() {
        return tolerances.stream().noneMatch(t -> Double.isNaN(t));
    }

    /** Whether objective values meet every tolerance (objectives without one always do). */
    public boolean meets(double[] values) {
        for (int i = 0; i < values.length; i++) {
            if (hasTolerance(i) && !(values[i] <= tolerances.get(i))) {
                return false;
            }
        }
        return true;
    }

    /** The objective values scaled by their tolerances (1 where an objective has none). */
    public double[] scaled(double[] values) {
        double[] out = new double[values.length];
        for (int i = 0; i < values.length; i++) {
            out[i] = hasTolerance(i) ? values[i] / tolerances.get(i) : values[i];
        }
        return out;
    }
}
