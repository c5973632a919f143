package handsim.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.config.ConfigException;
import handsim.config.Json;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("fast")
class LearnerConfigTest {

    @Test
    void defaultsParseAndRoundTripThroughJson() {
        LearnerConfig c = LearnTestSupport.config();
        assertEquals(java.util.List.of(64, 64), c.ddpg().actorHidden(), "paper sec. 3.7: two layers of 64");
        assertEquals(c, LearnerConfig.parse(Json.of("round trip", c.toJson())));
        assertEquals(LearnerConfig.Td3.OFF, c.ddpg().td3(), "no td3 block: plain DDPG");
        assertTrue(!c.toJson().get("ddpg").has("td3"), "and plain DDPG writes none back");
        LearnerConfig t = LearnTestSupport.config("ddpg.td3",
                "{\"twinCritics\": true, \"policyDelay\": 2, \"targetNoise\": 0.2, \"targetNoiseClip\": 0.5}");
        assertEquals(new LearnerConfig.Td3(true, 2, 0.2, 0.5), t.ddpg().td3());
        assertEquals(t, LearnerConfig.parse(Json.of("round trip", t.toJson())));
    }

    @Test
    void badValuesAreNamedWithTheirField() {
        ConfigException e = assertThrows(ConfigException.class, () -> LearnTestSupport.config("ddpg.tau", "2"));
        assertTrue(e.getMessage().contains("ddpg.tau") && e.getMessage().contains("got 2"), e.getMessage());
        e = assertThrows(ConfigException.class, () -> LearnTestSupport.config("exploration.noise", "\"pink\""));
        assertTrue(e.getMessage().contains("exploration.noise") && e.getMessage().contains("pink"), e.getMessage());
        e = assertThrows(ConfigException.class, () -> LearnTestSupport.config("ddpg.actorHidden", "[64, 0.5]"));
        assertTrue(e.getMessage().contains("ddpg.actorHidden") && e.getMessage().contains("0.5"), e.getMessage());
        e = assertThrows(ConfigException.class, () -> LearnTestSupport.config("ddpg.td3",
                "{\"twinCritics\": true, \"policyDelay\": 0, \"targetNoise\": 0.2, \"targetNoiseClip\": 0.5}"));
        assertTrue(e.getMessage().contains("ddpg.td3.policyDelay") && e.getMessage().contains("0"), e.getMessage());
        e = assertThrows(ConfigException.class, () -> LearnTestSupport.config("ddpg.replayCapacity", "10"));
        assertTrue(e.getMessage().contains("ddpg.replayCapacity") && e.getMessage().contains("batchSize"), e.getMessage());
    }

    @Test
    void unknownAndMissingFieldsAreRejected() {
        Json j = Json.parse("t", "{\"seed\": 1, \"ddpg\": {}}");
        ConfigException e = assertThrows(ConfigException.class, () -> LearnerConfig.parse(j));
        assertTrue(e.getMessage().contains("ddpg.actorHidden") && e.getMessage().contains("missing"), e.getMessage());
        var node = LearnTestSupport.config().toJson();
        ((com.fasterxml.jackson.databind.node.ObjectNode) node.get("training")).put("episodez", 3);
        e = assertThrows(ConfigException.class, () -> LearnerConfig.parse(Json.of("t", node)));
        assertTrue(e.getMessage().contains("training.episodez"), e.getMessage());
    }

    @Test
    void noiseScaleDecaysLinearly() {
        LearnerConfig.Exploration x = LearnTestSupport.config("exploration.sigma", "0.3", "exploration.sigmaFinal", "0.1",
                "exploration.sigmaDecaySteps", "100").exploration();
        assertEquals(0.3, x.sigmaAt(0), 1e-15);
        assertEquals(0.2, x.sigmaAt(50), 1e-15);
        assertEquals(0.1, x.sigmaAt(100), 1e-15);
        assertEquals(0.1, x.sigmaAt(1000), 1e-15);
    }
}
