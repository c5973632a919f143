package handsim.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;

import handsim.cards.study.Evaluation;
import handsim.cards.study.Objective;
import handsim.cards.study.PortableObjective;
import handsim.cards.study.RemoteTrials;
import handsim.cards.study.Study;
import handsim.cards.study.StudyConfig;
import handsim.config.Json;
import handsim.rollout.RemoteCalls;
import java.io.PrintStream;
import java.io.OutputStream;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A TPE study whose trials run through Spark in local mode ({@code local[2]}) writes the trial
 * files of the same study on threads, byte for byte but for the trials' wall times: trial k's
 * parameters come from the trials before k - P whoever runs them (Branin with P = 2, 16 trials,
 * the first 5 random, so that TPE suggests the rest).
 */
@Tag("fast")
class LocalSparkStudyTest {

    private static final String CONFIG = """
            {"objectives": [{"name": "regret", "direction": "minimize"}],
             "params": [{"name": "x", "low": -5, "high": 10}, {"name": "y", "low": 0, "high": 15}],
             "parallelTrials": 2, "sampler": {"nStartupTrials": 5}}""";

    /** Branin's regret, a pause that varies with x so that trials finish out of order. */
    record Branin() implements PortableObjective {
        @Override
        public Objective build() {
            return p -> {
                double x = p.get("x"), y = p.get("y"), b = 5.1 / (4 * Math.PI * Math.PI), c = 5 / Math.PI, t = 1 / (8 * Math.PI);
                Thread.sleep((long) (x + 5));
                return Evaluation.of(Math.pow(y - b * x * x + c * x - 6, 2) + 10 * (1 - t) * Math.cos(x) + 10 - 0.397887);
            };
        }
    }

    @Test
    void aStudyOnSparkWritesTheTrialFilesOfAStudyOnThreads(@TempDir Path tmp) throws Exception {
        StudyConfig config = StudyConfig.parse(Json.parse("test config", CONFIG));
        Study.openOrCreate(tmp.resolve("threads"), config, 9, Json.mapper().createObjectNode()).run(new Branin().build(), 16, 2, null);
        PrintStream quiet = new PrintStream(OutputStream.nullOutputStream());
        try (RemoteCalls calls = new SparkBackend().connect("local[2]", "handsim test", quiet);
                RemoteTrials trials = new RemoteTrials(calls, new Branin(), config, 9, 16)) {
            Study.openOrCreate(tmp.resolve("spark"), config, 9, Json.mapper().createObjectNode()).run(trials, 16, quiet);
        }
        assertEquals(16 + 2, SameBytes.assertSameFiles(tmp.resolve("threads"), tmp.resolve("spark"), List.of("study.json")),
                "16 trials, best.json and history.png");
    }
}
