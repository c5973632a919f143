package handsim.train;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.TestSupport;
import handsim.config.ConfigException;
import handsim.config.ConfigSet;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.CatchStyle;
import handsim.control.ControllerConfig;
import handsim.learn.EpisodeStats;
import handsim.learn.MetricsCsv;
import handsim.rollout.LocalRollouts;
import handsim.rollout.Rollouts;
import handsim.sim.Simulator;
import handsim.sim.ode.OdeSimulator;
import handsim.spec.RunConfigs;
import handsim.task.FlipTask;
import handsim.task.StateVector;
import handsim.taskdef.TaskDefinitions;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A training run on a tiny budget (4 episodes of at most 2 throws, 2 per round, updates from the
 * third decision on) writes a well-formed run folder, and a run stopped after its first
 * checkpoint and resumed ends exactly where an uninterrupted one does.
 */
@Tag("slow")
class TrainRunTest {

    private static TrainConfig tinyConfig() {
        return tinyConfig(Map.of());
    }

    /** The tiny run with further {@code --set} overrides. */
    private static TrainConfig tinyConfig(Map<String, String> more) {
        Path file = Home.resolve("configs/train/height.json");
        Map<String, String> kv = new java.util.HashMap<>(Map.of(
                "training.episodes", "4", "training.parallelEpisodes", "2", "training.maxDecisionsPerEpisode", "2",
                "training.checkpointEveryEpisodes", "2", "exploration.warmupSteps", "3", "ddpg.batchSize", "2",
                "ddpg.replayCapacity", "100", "run.workers", "1"));
        kv.putAll(more);
        return TrainConfig.parse(Json.of("tiny height run", Json.withOverrides(file.toString(), Json.load(file).node(), kv)));
    }

    private static ThrowEnvFactory envs() {
        return TestSupport.heightEnvs(ControllerConfig.load(Home.resolve("configs/controller.json")).throwSpace());
    }

    private static Rollouts<Simulator> rollouts() {
        return new LocalRollouts<>(1, () -> new OdeSimulator(TestSupport.model(), TestSupport.simConfig()));
    }

    @Test
    void aRunWritesItsFolderAndAResumedRunEndsLikeAnUninterruptedOne(@TempDir Path tmp) throws Exception {
        PrintStream quiet = new PrintStream(new ByteArrayOutputStream());
        Path whole = tmp.resolve("whole"), split = tmp.resolve("split");
        try (Rollouts<Simulator> r = rollouts()) {
            com.fasterxml.jackson.databind.node.ObjectNode started = Json.mapper().createObjectNode()
                    .put("command", "scripts/handsim train --config tiny.json").put("commit", "0123abc");
            TrainRun.start(whole, tinyConfig(), envs(), r, started).run(quiet);
            TrainRun.start(split, tinyConfig(), envs(), r, started).run(quiet, 2);
            assertEquals(2, MetricsCsv.read(split.resolve(TrainRun.METRICS)).size(), "the first invocation stopped after 2 episodes");
            TrainRun.resume(split, envs(), r).run(quiet);
        }
        for (String f : List.of("config.json", "run.json", "metrics.csv", "checkpoint.zip", "policy.json", "learning.png",
                "losses.png")) {
            assertTrue(Files.size(split.resolve(f)) > 0, f + " written");
        }
        assertSameRun(whole, split);
        Json provenance = Json.load(split.resolve(TrainRun.POLICY)).get("provenance");
        assertEquals("0123abc", provenance.string("commit"), "the policy names the commit that trained it");
        assertEquals("scripts/handsim train --config tiny.json", provenance.string("command"));
        assertEquals(tinyConfig().toJson(), TrainRun.savedConfig(split).toJson(), "the merged config is saved in the folder");
    }

    @Test
    void aFinishedRunExtendedToALargerBudgetEndsLikeARunGivenThatBudget(@TempDir Path tmp) throws Exception {
        PrintStream quiet = new PrintStream(new ByteArrayOutputStream());
        Path whole = tmp.resolve("whole"), extended = tmp.resolve("extended");
        TrainConfig twoEpisodes = TrainConfig.parse(Json.of("2 episodes", Json.withOverrides("tiny", tinyConfig().toJson(),
                Map.of("training.episodes", "2"))));
        try (Rollouts<Simulator> r = rollouts()) {
            TrainRun.start(whole, tinyConfig(), envs(), r, Json.mapper().createObjectNode()).run(quiet);
            TrainRun.start(extended, twoEpisodes, envs(), r, Json.mapper().createObjectNode()).run(quiet);
            assertEquals(2, MetricsCsv.read(extended.resolve(TrainRun.METRICS)).size(), "the first run finished at its budget");
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> TrainRun.extend(extended, 1, Json.mapper().createObjectNode()));
            assertTrue(e.getMessage().contains("1") && e.getMessage().contains("2"), e.getMessage());
            TrainRun.extend(extended, 4, Json.mapper().createObjectNode().put("command", "test"));
            TrainRun.resume(extended, envs(), r).run(quiet);
            // the same command again (a killed extension resumed) is no second extension
            TrainRun.extend(extended, 4, Json.mapper().createObjectNode().put("command", "again"));
        }
        assertSameRun(whole, extended);
        assertEquals(tinyConfig().toJson(), TrainRun.savedConfig(extended).toJson(), "the saved config has the new budget");
        var record = Json.load(extended.resolve(TrainRun.RUN_JSON)).node().get("extended").get(0);
        assertEquals(2, record.get("from").asInt());
        assertEquals(4, record.get("to").asInt());
        assertEquals("test", record.get("command").asText());
        assertEquals(1, Json.load(extended.resolve(TrainRun.RUN_JSON)).node().get("extended").size(), "one extension recorded");
    }

    /** The two run folders hold the same 4 episodes and policies that act alike, bit for bit. */
    private static void assertSameRun(Path whole, Path other) throws Exception {
        List<EpisodeStats> a = MetricsCsv.read(whole.resolve(TrainRun.METRICS)), b = MetricsCsv.read(other.resolve(TrainRun.METRICS));
        assertEquals(4, b.size());
        for (int i = 0; i < 4; i++) {
            EpisodeStats x = a.get(i), y = b.get(i);
            assertEquals(i + 1, y.episode());
            assertEquals(x.totalSteps(), y.totalSteps(), "decisions up to episode " + (i + 1));
            assertEquals(x.reward(), y.reward(), 0, "reward of episode " + (i + 1));
            assertEquals(x.q0(), y.q0(), 0, "Q0 of episode " + (i + 1));
            assertEquals(x.updates(), y.updates());
        }
        assertTrue(a.get(3).updates() > 0, "the run got past the warm-up and learned");
        ThrowPolicyFile pa = ThrowPolicyFile.load(whole.resolve(TrainRun.POLICY)), pb = ThrowPolicyFile.load(other.resolve(TrainRun.POLICY));
        double[] state = new double[StateVector.Encoding.PAPER.baseSize() + 1];
        state[StateVector.Encoding.PAPER.baseSize()] = 1.2;
        assertArrayEquals(pa.policy().act(state), pb.policy().act(state), 0);
    }

    /**
     * {@code train --init-actor POLICY.json} (its DATASET_OR_ACTOR): the run's actor starts
     * as the shipped height policy, acting as it does up to round-off (1e-9: the same weights,
     * float arithmetic in another order), and the policy is copied into the run. A policy of
     * another task, or a config without {@code pretrain.policyObservations}, is refused before
     * anything is written.
     */
    @Test
    void aRunMayStartItsActorAsATrainedPolicy(@TempDir Path tmp) throws Exception {
        Path shipped = ThrowPolicyFile.shipped("height", "sphere");
        handsim.learn.Policy policy = ThrowPolicyFile.load(shipped).policy();
        TrainConfig c = tinyConfig(Map.of("pretrain.policyObservations", "10000"));
        try (Rollouts<Simulator> r = rollouts()) {
            ThrowEnvFactory heightSpace = TestSupport.heightEnvs(TestSupport.heightTask(null).throwSpace(
                    ControllerConfig.load(Home.resolve("configs/controller.json")).throwSpace())); // as train makes it
            TrainRun run = TrainRun.start(tmp.resolve("tuned"), c, heightSpace, r, Json.mapper().createObjectNode(), shipped);
            java.util.SplittableRandom rng = new java.util.SplittableRandom(3);
            for (int i = 0; i < 20; i++) {
                double[] obs = rng.doubles(policy.observationSize(), -1, 2).toArray();
                assertArrayEquals(policy.act(obs), run.trainer().agent().act(obs), 1e-9, "observation " + i);
            }
            assertEquals(Files.readString(shipped), Files.readString(tmp.resolve("tuned").resolve(TrainRun.INIT_POLICY)));

            IllegalArgumentException unset = assertThrows(IllegalArgumentException.class, () -> TrainRun.start(
                    tmp.resolve("unset"), tinyConfig(), heightSpace, r, Json.mapper().createObjectNode(), shipped));
            assertTrue(unset.getMessage().contains("pretrain.policyObservations"), unset.getMessage());
            IllegalArgumentException other = assertThrows(IllegalArgumentException.class, () -> TrainRun.start(
                    tmp.resolve("other"), c, heightSpace, r, Json.mapper().createObjectNode(), ThrowPolicyFile.shipped("flip", "can")));
            assertTrue(other.getMessage().contains("flip task"), other.getMessage());
            assertFalse(Files.exists(tmp.resolve("unset")) || Files.exists(tmp.resolve("other")), "nothing written");
        }
    }

    @Test
    void setMayGiveAnOptionalFieldTheFileLeavesOutButAMisspeltOneIsNamed() {
        Path file = Home.resolve("configs/train/height.json");
        JsonNode node = Json.load(file).node();
        assertFalse(node.get("training").has("criticWarmupDecisions"), "the height run leaves the optional field out");
        TrainConfig c = TrainConfig.parse(Json.of("set", Json.withOverrides(file.toString(), node,
                Map.of("training.criticWarmupDecisions", "100"))));
        assertEquals(100, c.learner().training().criticWarmupDecisions());
        ConfigException e = assertThrows(ConfigException.class, () -> TrainConfig.parse(
                Json.of("typo", Json.withOverrides(file.toString(), node, Map.of("training.criticWarmupDecisionz", "100")))));
        assertTrue(e.getMessage().contains("criticWarmupDecisionz") && e.getMessage().contains("unknown field"), e.getMessage());
    }

    @Test
    void aRunMayEndItsEpisodesAtTheFirstFailedThrowAndSavesThatOnlyWhenSet() {
        Path file = Home.resolve("configs/train/flip.json");
        JsonNode node = Json.load(file).node();
        TrainConfig plain = TrainConfig.parse(Json.of("plain", node));
        assertFalse(plain.run().endAtFailedThrow());
        assertFalse(plain.toJson().get("run").has("endAtFailedThrow"));
        TrainConfig ending = TrainConfig.parse(Json.of("set", Json.withOverrides(file.toString(), node,
                Map.of("run.endAtFailedThrow", "true"))));
        assertTrue(ending.run().endAtFailedThrow());
        assertEquals(ending, TrainConfig.parse(Json.of("saved", ending.toJson())), "the run folder's config gives it back");
    }

    /** The flip task a run trains on: the task's file with the run's taskSet applied. */
    private static FlipTask flipTaskOf(TrainConfig.Run run) {
        return new RunConfigs(ConfigSet.fromFiles(Map.of(TaskDefinitions.file("flip"), run.taskSet()))).flip().newTask("can");
    }

    @Test
    void aFlipRunCatchesAndRestsAsItsTaskSetSays() {
        // configs/train/flip.json trains with the controller's own catch (the shipped can policy was trained so), not the
        // task's level catch, and without the can's arm rest: both as fields of the task's file changed; the folder keeps them
        Path file = Home.resolve("configs/train/flip.json");
        TrainConfig flip = TrainConfig.load(file);
        assertEquals(flip, TrainConfig.parse(Json.of("saved", flip.toJson())), "the run folder's config gives it back");
        ControllerConfig base = ControllerConfig.load(Home.resolve("configs/controller.json"));
        FlipTask trained = flipTaskOf(flip.run());
        assertEquals(new CatchStyle(0, 0.7), trained.controller(base).catchAfterThrow().orElseThrow(), "the task catches as the run says");
        assertTrue(trained.controller(base).armRest().isEmpty(), "and leaves the arm to the IK");
        assertTrue(TestSupport.configs().flip().newTask("can").controller(base).armRest().isPresent(), "the task's can has an arm rest");
        for (String name : new String[] {"flip", "flip-opening", "flip-warmstart", "flip-dagger"}) {
            TrainConfig.Run run = TrainConfig.Run.parse(Json.load(Home.resolve("configs/train/" + name + ".json")).get("run"));
            assertTrue(flipTaskOf(run).controller(base).armRest().isEmpty(), name + ": the shipped can policies were trained without it");
        }
        TrainConfig resting = TrainConfig.parse(Json.of("set", Json.withOverrides(file.toString(), Json.load(file).node(),
                Map.of("run.taskSet", "{}"))));
        assertTrue(flipTaskOf(resting.run()).controller(base).armRest().isPresent(), "an empty taskSet trains with the task's own arm rest");
        assertEquals(resting, TrainConfig.parse(Json.of("saved", resting.toJson())), "and its folder's config keeps it");
    }

    @Test
    void aRunSectionThatNamesTheCatchAndTheArmRestReadsAsTheTaskSetTheyStandFor() {
        // run folders whose run section names catch and armRest (no taskSet): armRest absent or false leaves the can's arm
        // rest out, catch replaces the task's catch
        ObjectNode run = (ObjectNode) Json.load(Home.resolve("configs/train/height.json")).node().deepCopy();
        ObjectNode r = (ObjectNode) run.get("run");
        r.put("task", "flip").put("object", "can");
        r.putObject("catch").put("planeShift", 0).put("velocityFraction", 0.7);
        TrainConfig saved = TrainConfig.parse(Json.of("saved", run));
        assertEquals(Map.of("objects.can.catch", "{\"planeShift\":0,\"velocityFraction\":0.7}", "objects.can.armRest", "null"),
                saved.run().taskSet());
        r.put("armRest", true);
        assertEquals(Map.of("objects.can.catch", "{\"planeShift\":0,\"velocityFraction\":0.7}"),
                TrainConfig.parse(Json.of("saved", run)).run().taskSet(), "armRest true keeps the task's arm rest");
        ObjectNode height = (ObjectNode) Json.load(Home.resolve("configs/train/height.json")).node().deepCopy();
        ((ObjectNode) height.get("run")).put("armRest", true);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> TrainConfig.parse(Json.of("height", height)));
        assertTrue(e.getMessage().contains("arm rest") && e.getMessage().contains("height"), e.getMessage());
    }

    @Test
    void aConfigNamesAnUnknownStateEncoding() {
        Path file = Home.resolve("configs/train/height.json");
        ConfigException e = assertThrows(ConfigException.class, () -> TrainConfig.parse(
                Json.of("bad", Json.withOverrides(file.toString(), Json.load(file).node(), Map.of("run.state", "euler")))));
        assertTrue(e.getMessage().contains("state") && e.getMessage().contains("euler"), e.getMessage());
        assertEquals(StateVector.Encoding.PAPER, tinyConfig().run().state(), "the height run keeps the printed state");
    }
}
