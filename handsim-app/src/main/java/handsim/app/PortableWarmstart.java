package handsim.app;

import com.fasterxml.jackson.databind.JsonNode;
import handsim.config.ConfigSet;
import handsim.config.Json;
import handsim.rollout.PortableTask;
import handsim.rollout.RolloutTask;
import handsim.sim.Simulator;
import handsim.spec.RunConfigs;
import handsim.train.Warmstart;
import handsim.train.WarmstartThrows;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * A warm start's generation of throws in the form that travels to a cluster: the warm-start
 * config and the run's configuration documents as read (JSON text), and each throw's initial
 * condition seed and action. An executor rebuilds the run's environments from them alone and
 * plays the throws by index.
 *
 * @param config the warm-start config ({@link Warmstart.Config#toJson})
 * @param documents the run's configuration documents as read ({@link ConfigSet#toJson})
 */
record PortableWarmstart(String config, String documents, int generation, long[] seeds, double[][] actions)
        implements PortableTask<Simulator> {

    private static final long serialVersionUID = 1L;

    /** What ships each generation of the warm start {@code c} read with {@code configs}. */
    static WarmstartThrows.Shipper shipper(Warmstart.Config c, RunConfigs configs) {
        String config = c.toJson().toString();
        return (generation, candidates) -> new PortableWarmstart(config, configs.files().toJson().toString(), generation,
                candidates.stream().mapToLong(WarmstartThrows.Candidate::seed).toArray(),
                candidates.stream().map(WarmstartThrows.Candidate::action).toArray(double[][]::new));
    }

    @Override
    public RolloutTask<Simulator, JsonNode> rebuild() {
        Warmstart.Config c = Warmstart.Config.parse(Json.parse("the warm start's config", config));
        RunConfigs configs = new RunConfigs(ConfigSet.replaying(Json.parse("the warm start's documents", documents)));
        List<WarmstartThrows.Candidate> candidates = new ArrayList<>();
        for (int j = 0; j < seeds.length; j++) {
            candidates.add(new WarmstartThrows.Candidate(seeds[j], actions[j]));
        }
        return WarmstartThrows.rebuilt(TrainCommand.environments(c.train().run(), configs), candidates);
    }

    @Override
    public String what() {
        return "warm-start throws of generation " + generation;
    }

    @Override
    public String label(int index) {
        return String.format(Locale.ROOT, "throw %d of generation %d (initial condition seed %d)", index, generation, seeds[index]);
    }
}
