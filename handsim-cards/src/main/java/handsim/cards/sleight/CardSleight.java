package handsim.cards.sleight;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.contact.BudgetExceeded;
import handsim.cards.sim.SimState;
import handsim.cards.sim.SoftWorld;
import handsim.cards.study.Objective;
import handsim.cards.study.StudyConfig;
import handsim.config.Json;
import java.util.List;
import java.util.Map;

/**
 * A card sleight as a function of its bone trajectory's parameters (thesis 3.2.4): what the
 * commands run, record, optimise and replay. A trial depends on its configs and parameters
 * alone, so it may run on any thread or machine and give the same result; each call builds its
 * own simulator.
 */
public interface CardSleight {

    /** The sleight's command-line name: snap, double-lift. */
    String name();

    /** Its name in prose: Card Snapping, Double Lift. */
    String title();

    /** The scene the trials run in (its bodies are what a recording draws). */
    SoftWorld world();

    /** What the trial is built from (configs as read, mesh, card preset), for a study's record. */
    ObjectNode inputs();

    /** The fingertip resolution's name. */
    String meshName();

    /** The parameters' names, as a study config must list them. */
    List<String> paramNames();

    /** The config's default parameters, by name. */
    Map<String, Double> defaults();

    /** Parameters read from a JSON object (a --params file), validated; the error names the field. */
    Map<String, Double> parseParams(Json j);

    /** The state a trial with {@code params} starts from (the checkpoint, fingers placed). */
    SimState startState(Map<String, Double> params);

    /** One trial, {@code listener} (may be null) told after every step. */
    Outcome run(Map<String, Double> params, TrialCost.StepListener listener);

    /** Requires a search space every point of which is a valid trial; the error names {@code source} and the field. */
    void checkSearchSpace(StudyConfig config, String source);

    /** Simulated steps between recorded frames. */
    int frameEvery();

    /** The trial as a study's objective; a trial past its {@link handsim.cards.sim.TrialBudget} fails, saying which. */
    default Objective objective() {
        return p -> {
            try {
                return run(p.values(), null).evaluation();
            } catch (BudgetExceeded e) {
                throw new Objective.TrialFailed("past its budget: " + e.getMessage(), e);
            }
        };
    }

    /**
     * What a trial gave: the objective values (the study config's order), named figures
     * (SI units) kept with it, its cost, and lines that say what happened in words and numbers.
     */
    record Outcome(double[] values, Map<String, Double> figures, TrialCost cost, List<String> report) {

        public Outcome {
            values = values.clone();
            figures = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(figures));
            report = List.copyOf(report);
        }

        @Override
        public double[] values() {
            return values.clone();
        }

        /** The values and figures as a study records them. */
        public handsim.cards.study.Evaluation evaluation() {
            handsim.cards.study.Evaluation e = handsim.cards.study.Evaluation.of(values);
            for (Map.Entry<String, Double> f : figures.entrySet()) {
                e = e.with(f.getKey(), f.getValue());
            }
            return cost.addTo(e);
        }

        /** As JSON (result.json): parameters, values, figures and cost. */
        public ObjectNode toJson(Map<String, Double> params, List<String> objectiveNames) {
            ObjectNode o = Json.mapper().createObjectNode();
            ObjectNode p = o.putObject("params");
            params.forEach(p::put);
            ObjectNode v = o.putObject("objectives");
            for (int i = 0; i < values.length; i++) {
                v.put(i < objectiveNames.size() ? objectiveNames.get(i) : "objective" + i, values[i]);
            }
            figures.forEach(o::put);
            cost.putInto(o);
            return o;
        }
    }
}
