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
    static TrainingConfig config(String... keyValues) {
        Map<String, String> overrides = new LinkedHashMap<>();
        for (int i = 0; i < keyValues.length; i += 2) {
            overrides.put(keyValues[i], keyValues[i + 1]);
        }
        Json defaults = Json.load(Home.resolve("configs/train/ddpg-defaults.json"));
        return TrainingConfig.parse(Json.of("test config", Json.withOverrides("test config", defaults.node(), overrides)));
    }
}
