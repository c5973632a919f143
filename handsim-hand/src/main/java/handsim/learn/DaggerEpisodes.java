package handsim.learn;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import java.util.ArrayList;
import java.util.List;

/**
 * A DAgger episode as JSON that reads back to the same episode bit for bit (numbers in Java's
 * shortest round-tripping form, NaN as "NaN"): how a played episode travels back from a
 * cluster's executor, and how the driver hands it to the demonstration set.
 */
public final class DaggerEpisodes {

    private DaggerEpisodes() {
    }

    public static JsonNode toJson(Dagger.Episode e) {
        JsonNodeFactory f = JsonNodeFactory.instance;
        ObjectNode o = f.objectNode();
        Dagger.Request r = e.request();
        o.put("round", r.round()).put("episode", r.episode()).put("envSeed", r.envSeed()).put("labelSeed", r.labelSeed())
                .put("maxDecisions", r.maxDecisions()).put("executeLabel", r.executeLabel());
        ArrayNode visits = o.putArray("visits");
        for (Dagger.Visit v : e.visits()) {
            ObjectNode vo = visits.addObject();
            vo.set("observation", Json.array(v.observation()));
            vo.set("proposal", Json.array(v.proposal()));
            Demonstration l = v.label();
            ObjectNode lo = vo.putObject("label");
            if (l.action() == null) {
                lo.putNull("action");
            } else {
                lo.set("action", Json.array(l.action()));
            }
            lo.put("proposalSucceeded", l.proposalSucceeded()).put("tries", l.tries()).put("robustness", l.robustness());
            ArrayNode trials = lo.putArray("trials");
            for (Demonstration.Trial t : l.trials()) {
                ObjectNode to = trials.addObject();
                to.set("action", Json.array(t.action()));
                to.put("success", t.success()).put("reward", t.reward());
                to.set("outcome", Json.array(t.outcome()));
            }
        }
        return o;
    }

    public static Dagger.Episode fromJson(JsonNode o) {
        Dagger.Request r = new Dagger.Request(o.get("round").asInt(), o.get("episode").asInt(), o.get("envSeed").asLong(),
                o.get("labelSeed").asLong(), o.get("maxDecisions").asInt(), o.get("executeLabel").asBoolean());
        List<Dagger.Visit> visits = new ArrayList<>();
        for (JsonNode v : o.get("visits")) {
            JsonNode l = v.get("label");
            List<Demonstration.Trial> trials = new ArrayList<>();
            for (JsonNode t : l.get("trials")) {
                trials.add(new Demonstration.Trial(numbers(t.get("action")), t.get("success").asBoolean(), t.get("reward").asDouble(),
                        numbers(t.get("outcome"))));
            }
            Demonstration label = new Demonstration(l.get("action").isNull() ? null : numbers(l.get("action")),
                    l.get("proposalSucceeded").asBoolean(), l.get("tries").asInt(), l.get("robustness").asDouble(), trials);
            visits.add(new Dagger.Visit(numbers(v.get("observation")), numbers(v.get("proposal")), label));
        }
        return new Dagger.Episode(r, visits);
    }

    /** An array's numbers; asDouble reads "NaN" (as JSON has no NaN) back as NaN. */
    private static double[] numbers(JsonNode a) {
        double[] x = new double[a.size()];
        for (int i = 0; i < x.length; i++) {
            x[i] = a.get(i).asDouble();
        }
        return x;
    }
}
