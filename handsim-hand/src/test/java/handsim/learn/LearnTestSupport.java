package handsim.learn;

import handsim.config.Home;
import handsim.config.Json;
import java.util.LinkedHashMap;
import java.util.Map;

/** Configs for learner tests: the shipped defaults with a few fields overridden. */
final class LearnTestSupport {

    private LearnTestSupport() {
    }

    /** {@code configs/train/ddpg-defaults.json} with overrides given as "path", "value" pairs. */
    static LearnerConfig config(String... keyValues) {
        Map<String, String> overrides = new LinkedHashMap<>();
        for (int i = 0; i < keyValues.length; i += 2) {
            overrides.put(keyValues[i], keyValues[i + 1]);
        }
        Json defaults = Json.load(Home.resolve("configs/train/ddpg-defaults.json"));
        return LearnerConfig.parse(Json.of("test config", Json.withOverrides("test config", defaults.node(), overrides)));
    }

    /** Mean reward per decision of the deterministic policy over {@code episodes} fresh episodes. */
    static double meanReward(Env env, Policy policy, int episodes, long seed) {
        double sum = 0;
        int n = 0;
        Rng seeds = new Rng(seed);
        for (int e = 0; e < episodes; e++) {
            EpisodePlayer.Episode ep = EpisodePlayer.play(env, new EpisodePlayer.Request(seeds.nextLong(), 0, 0, false, 1000), policy::act,
                    config().exploration(), t -> { });
            sum += ep.reward();
            n += ep.transitions().size();
        }
        return sum / n;
    }
}
