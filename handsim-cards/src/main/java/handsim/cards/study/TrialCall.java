package handsim.cards.study;

import handsim.config.Json;
import handsim.rollout.PortableCall;
import java.util.HashMap;
import java.util.Map;

/**
 * One trial as a call to a cluster: the study's config (JSON text), the trial's number and
 * parameters, and the objective's portable form; the executor builds the objective once (kept
 * under the driver's key) and returns the trial's record as JSON, which reads back bit for bit.
 */
record TrialCall(PortableObjective objective, String objectiveKey, String config, long seed, int number, double[] params)
        implements PortableCall<String> {

    private static final long serialVersionUID = 1L;

    /** The objectives this executor built, by key (a study builds one). */
    private static final Map<String, Objective> BUILT = new HashMap<>();

    @Override
    public String call() {
        Objective o;
        synchronized (BUILT) {
            o = BUILT.computeIfAbsent(objectiveKey, k -> objective.build());
        }
        StudyConfig c = StudyConfig.fromJson("the study's config", Json.parse("the study's config", config).node());
        return Study.trial(o, c, number, params).toJson(c).toString();
    }

    @Override
    public String label() {
        return "trial " + number + " (study seed " + seed + ")";
    }
}
