package handsim.cards.study;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.config.ConfigException;
import handsim.config.Json;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A three-objective study with tolerances (as Double Lift's): the chosen trial is the Pareto
 * trial closest to zero once each objective is divided by its tolerance; any {@link
 * TrialExecutor} that evaluates the same objective gives the same study as the thread pool; the
 * Pareto figure is written; and a tolerance on a maximised objective is refused.
 */
@Tag("fast")
class ChosenTrialTest {

    private static StudyConfig config(String sampler) {
        return StudyConfig.parse(Json.parse("test config", """
                {"objectives": [{"name": "a", "direction": "minimize", "tolerance": 0.1},
                                {"name": "b", "direction": "minimize", "tolerance": 0.1},
                                {"name": "c", "direction": "minimize", "tolerance": 0.01}],
                 "params": [{"name": "x", "low": 0, "high": 1}, {"name": "y", "low": 0, "high": 1}],
                 "parallelTrials": 2,
                 "sampler": %s}
                """.formatted(sampler)));
    }

    /** Three objectives that no point sets to zero together: |x − 0.3|, |y − 0.6|, (x − y)² / 10. */
    private static Evaluation objective(TrialParams p) {
        double x = p.get("x"), y = p.get("y");
        return Evaluation.of(Math.abs(x - 0.3), Math.abs(y - 0.6), (x - y) * (x - y) / 10);
    }

    /** Evaluates each trial when it is taken, in the reverse order of submission: timing and order are its own. */
    private static final class Backwards implements TrialExecutor {
        private final Deque<int[]> numbers = new ArrayDeque<>();
        private final Deque<double[]> params = new ArrayDeque<>();
        private final StudyConfig config;

        Backwards(StudyConfig config) {
            this.config = config;
        }

        @Override
        public int slots() {
            return 2;
        }

        @Override
        public String describe() {
            return "backwards";
        }

        @Override
        public void start(int number, double[] p) {
            numbers.push(new int[] {number});
            params.push(p.clone());
        }

        @Override
        public TrialRecord next() {
            return Study.trial(ChosenTrialTest::objective, config, numbers.pop()[0], params.pop());
        }

        @Override
        public void close() {
        }
    }

    @Test
    void theChosenTrialIsTheParetoTrialNearestZeroInUnitsOfTolerance(@TempDir Path tmp) throws Exception {
        for (String sampler : List.of("{}", "{\"multivariate\": true}")) {
            StudyConfig c = config(sampler);
            Path dir = tmp.resolve(sampler.length() > 2 ? "multivariate" : "independent");
            Study study = Study.openOrCreate(dir, c, 3, Json.mapper().createObjectNode());
            study.run(ChosenTrialTest::objective, 40, 2, null);

            TrialRecord chosen = study.chosen().orElseThrow();
            assertTrue(study.paretoFront().contains(chosen), "the chosen trial is on the Pareto front");
            double best = Double.POSITIVE_INFINITY;
            for (TrialRecord t : study.paretoFront()) {
                double[] s = c.scaled(t.values());
                best = Math.min(best, Math.sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]));
            }
            double[] s = c.scaled(chosen.values());
            assertEquals(best, Math.sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]), 0.0, "nearest to zero of the front, scaled");
            assertEquals(chosen.number(), Json.load(dir.resolve(Study.BEST_FILE)).get("chosen").integer("number"));
            assertTrue(Files.size(dir.resolve("pareto.png")) > 1000, "the Pareto figure");

            // another executor, which evaluates in its own order, gives the same study trial for trial
            Path other = tmp.resolve("other-" + dir.getFileName());
            Study again = Study.openOrCreate(other, c, 3, Json.mapper().createObjectNode());
            again.run(new Backwards(c), 40, null);
            for (int i = 0; i < 40; i++) {
                assertArrayEquals(study.trials().get(i).params(), again.trials().get(i).params(), 0.0, "trial " + i);
                assertArrayEquals(study.trials().get(i).values(), again.trials().get(i).values(), 0.0, "trial " + i);
            }
        }
    }

    @Test
    void toleranceChecksAndRefusals() {
        StudyConfig c = config("{}");
        assertTrue(c.meets(new double[] {0.1, 0.05, 0.01}), "a value at its tolerance meets it");
        assertFalse(c.meets(new double[] {0.1, 0.05, 0.0100001}));
        assertArrayEquals(new double[] {2, 0.5, 3}, c.scaled(new double[] {0.2, 0.05, 0.03}), 1e-12);
        ConfigException e = assertThrows(ConfigException.class, () -> StudyConfig.parse(Json.parse("bad", """
                {"objectives": [{"name": "a", "direction": "maximize", "tolerance": 1}],
                 "params": [{"name": "x", "low": 0, "high": 1}], "parallelTrials": 1}
                """)));
        assertTrue(e.getMessage().contains("tolerance"), e.getMessage());
        assertThrows(ConfigException.class, () -> StudyConfig.parse(Json.parse("bad", """
                {"objectives": [{"name": "a", "direction": "minimize", "tolerance": 0}],
                 "params": [{"name": "x", "low": 0, "high": 1}], "parallelTrials": 1}
                """)));
    }
}
