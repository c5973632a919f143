package handsim.learn;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

@Tag("fast")
class CheckpointTest {

    /** A short run that updates from its second episode on. */
    private static LearnerConfig config(String... more) {
        List<String> kv = new ArrayList<>(List.of("seed", "7", "ddpg.batchSize", "16", "exploration.warmupSteps", "20",
                "exploration.noise", "\"ou\"", "exploration.sigmaDecaySteps", "100", "training.episodes", "8",
                "training.movingAverageWindow", "3", "training.checkpointEveryEpisodes", "4"));
        kv.addAll(List.of(more));
        return LearnTestSupport.config(kv.toArray(String[]::new));
    }

    @Test
    void resumedRunContinuesExactlyAsTheUninterruptedOne(@TempDir Path dir) throws IOException {
        resumesExactly(dir, config());
    }

    /** The same with TD3: the second critic and its target are saved too (the target noise draws from the saved replay generator). */
    @Test
    void resumedTd3RunContinuesExactlyAsTheUninterruptedOne(@TempDir Path dir) throws IOException {
        resumesExactly(dir, config("ddpg.td3",
                "{\"twinCritics\": true, \"policyDelay\": 2, \"targetNoise\": 0.2, \"targetNoiseClip\": 0.5}"));
    }

    private static void resumesExactly(Path dir, LearnerConfig config) throws IOException {
        Env env = new ToyEnvs.GoalReaching(5);
        Path ckpt = dir.resolve("checkpoint.zip");

        // uninterrupted: 8 episodes; the checkpoint is written after episode 4 (and 8)
        List<EpisodeStats> straight = new ArrayList<>();
        Trainer a = Trainer.create(config, 4, 3);
        a.train(env, null, straight::add, null);
        Trainer b = Trainer.create(config, 4, 3);
        for (int e = 0; e < 4; e++) {
            b.runEpisode(env, s -> { });
        }
        b.checkpoint(ckpt);
        double[] probe = {0.2, -0.3, 0.5, 0.1};
        double[] actionBefore = b.agent().act(probe);
        double qBefore = b.agent().q(probe, actionBefore);

        Trainer resumed = Trainer.resume(ckpt);
        assertArrayEquals(actionBefore, resumed.agent().act(probe), 0.0, "identical actions after load");
        assertEquals(qBefore, resumed.agent().q(probe, actionBefore), 0.0);
        assertEquals(4, resumed.episodes());
        assertEquals(b.steps(), resumed.steps());
        assertEquals(b.agent().replaySize(), resumed.agent().replaySize());

        List<EpisodeStats> continued = new ArrayList<>();
        resumed.train(env, null, continued::add, null);
        assertEquals(4, continued.size());
        assertTrue(continued.get(3).updates() > 0, "the continuation must include updates to test anything");
        for (int i = 0; i < 4; i++) {
            assertEquals(withoutWallTime(straight.get(4 + i)), withoutWallTime(continued.get(i)), "episode " + (5 + i));
        }
    }

    @Test
    void aFailedSaveLeavesThePreviousFileIntact(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("checkpoint.zip");
        Files.writeString(file, "previous checkpoint");
        IOException e = assertThrows(IOException.class, () -> handsim.report.Outputs.write(file, out -> {
            out.write(new byte[1000]);
            throw new IOException("killed while writing");
        }));
        // the failure names the file it was writing and keeps the reason
        assertEquals(file + ": cannot write it: killed while writing", e.getMessage());
        assertEquals("previous checkpoint", Files.readString(file));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(file), files.toList(), "no temporary file left behind");
        }
    }

    private static EpisodeStats withoutWallTime(EpisodeStats s) {
        return new EpisodeStats(s.episode(), s.totalSteps(), s.decisions(), s.reward(), s.averageReward(), s.q0(),
                s.criticLoss(), s.actorLoss(), s.updates(), s.terminal(), s.sigma(), 0);
    }
}
