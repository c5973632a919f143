package handsim.train;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.learn.Env;
import handsim.rollout.PortableTask;
import handsim.rollout.RolloutTask;
import handsim.rollout.ShippableTask;
import handsim.sim.Simulator;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;

/**
 * The throws a warm start tries, a CMA-ES generation of every search at a time: each candidate is
 * one throw from one initial condition (its episode seed), a pure function of the seed and the
 * action, so the throws of a generation run on any worker, here or on a cluster, in any order.
 */
public final class WarmstartThrows {

    /** A throw to try: the initial condition's episode seed and the action (in [-1, 1]^k). */
    public record Candidate(long seed, double[] action) {
    }

    /** What a throw gave: its reward, and the state of its initial condition (the decision's observation). */
    public record Outcome(double reward, double[] state) {

        public JsonNode toJson() {
            ObjectNode o = Json.mapper().createObjectNode().put("reward", reward);
            o.set("state", Json.array(state));
            return o;
        }

        public static Outcome fromJson(JsonNode j) {
            double[] state = new double[j.get("state").size()];
            for (int i = 0; i < state.length; i++) {
                state[i] = j.get("state").get(i).asDouble(); // asDouble reads "NaN" back as NaN
            }
            return new Outcome(j.get("reward").asDouble(), state);
        }
    }

    /** A generation's throws in the form that travels to a cluster (the app builds it from the run's configuration documents). */
    @FunctionalInterface
    public interface Shipper {
        PortableTask<Simulator> ship(int generation, List<Candidate> candidates);
    }

    private final ThrowEnvFactory envs;
    /** Each worker's environment, made on its first throw and kept for the run's later generations. */
    private final Map<Simulator, ThrowEnv> environments = Collections.synchronizedMap(new IdentityHashMap<>());

    public WarmstartThrows(ThrowEnvFactory envs) {
        this.envs = envs;
    }

    /** Throw {@code c} in {@code env}: reset to its initial condition, the action, the reward. */
    public static Outcome play(ThrowEnv env, Candidate c) {
        double[] state = env.reset(c.seed());
        Env.Step step = env.step(c.action());
        return new Outcome(step.reward(), state);
    }

    /** The throws of one generation as a rollout task: run here by the workers' environments, shipped by {@code shipper} if not null. */
    RolloutTask<Simulator, Outcome> task(int generation, List<Candidate> candidates, Shipper shipper) {
        RolloutTask<Simulator, Outcome> local = sim -> {
            ThrowEnv env = environments.computeIfAbsent(sim, envs::create);
            return j -> play(env, candidates.get(j));
        };
        return shipper == null ? local : new ShippableTask<>(local, shipper.ship(generation, candidates), Outcome::fromJson);
    }

    /** A rollout task of {@code candidates} in a JVM that rebuilt {@code envs}: what an executor runs. */
    public static RolloutTask<Simulator, JsonNode> rebuilt(ThrowEnvFactory envs, List<Candidate> candidates) {
        Function<Simulator, ThrowEnv> env = envs::create;
        return sim -> {
            ThrowEnv e = env.apply(sim);
            return j -> play(e, candidates.get(j)).toJson();
        };
    }
}
