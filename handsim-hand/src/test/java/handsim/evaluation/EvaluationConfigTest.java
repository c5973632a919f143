package handsim.evaluation;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.config.ConfigException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class EvaluationConfigTest {

    @TempDir
    Path dir;

    private static final String VALID = """
            {"sensitivityThrows": 5, "boxBands": 4, "plannedProgressEvery": 10,
             "flipBins": {"angleBinDeg": 15, "earlyThrows": 5, "catchDistanceEdges": [0.04, 0.08]}}""";

    private EvaluationConfig load(String text) throws IOException {
        Path file = dir.resolve("evaluation.json");
        Files.writeString(file, text);
        return EvaluationConfig.load(file);
    }

    @Test
    void theShippedFileGivesTheFlipSummarysBins() throws IOException {
        // configs/evaluation.json: 15 deg bins (six from 0 to 90), throws 2-5 early, catches cut at 4 and 8 cm
        EvaluationConfig c = EvaluationConfig.load(Path.of("configs/evaluation.json"));
        assertEquals(Math.toRadians(15), c.flipBins().angle(), 1e-12);
        assertEquals(5, c.flipBins().earlyThrows());
        assertArrayEquals(new double[] {0.04, 0.08}, c.flipBins().catchDistanceEdges(), 0);
        assertEquals(c.flipBins().angle(), load(VALID).flipBins().angle(), 0, "the test's own copy reads the same");
    }

    @Test
    void badBinsAreRefusedNamingTheFieldAndTheValue() throws IOException {
        // each field of flipBins is checked where it is read; the error names its path and the value given
        String[][] cases = {
            {"\"angleBinDeg\": 15", "\"angleBinDeg\": 20", "flipBins.angleBinDeg", "20"},
            {"\"angleBinDeg\": 15", "\"angleBinDeg\": 0", "flipBins.angleBinDeg", "0"},
            {"\"earlyThrows\": 5", "\"earlyThrows\": 0", "flipBins.earlyThrows", "0"},
            {"[0.04, 0.08]", "[0.08, 0.04]", "flipBins.catchDistanceEdges", "0.08, 0.04"},
            {"[0.04, 0.08]", "[0, 0.08]", "flipBins.catchDistanceEdges", "0.0, 0.08"},
            {"\"earlyThrows\": 5", "\"earlyThrows\": 5, \"early\": 3", "flipBins.early", "early"},
        };
        for (String[] c : cases) {
            String text = VALID.replace(c[0], c[1]);
            ConfigException e = assertThrows(ConfigException.class, () -> load(text), c[1]);
            assertTrue(e.getMessage().contains(c[2]) && e.getMessage().contains(c[3]), c[1] + ": " + e.getMessage());
        }
    }

    @Test
    void edgesAreCopiedInAndOut() {
        double[] edges = {0.04, 0.08};
        var bins = new FlipReport.Bins(1, 5, edges);
        edges[0] = 1;
        bins.catchDistanceEdges()[1] = 1;
        assertArrayEquals(new double[] {0.04, 0.08}, bins.catchDistanceEdges(), 0, "the record's edges are its own");
    }
}
