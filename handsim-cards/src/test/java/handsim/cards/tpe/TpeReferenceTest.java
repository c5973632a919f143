package handsim.cards.tpe;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The deterministic parts of the TPE sampler against Optuna 3.6.1 itself: values in
 * src/test/resources/tpe/optuna-reference.json, written by optuna_reference.py beside it (its
 * docstring has the command). Recorded histories of 11 to 300 trials, float (linear and log) and
 * integer (linear and log) parameters, one to three objectives.
 *
 * <p>Tolerances: 1e-12 relative for weights, means and bandwidths (the same formulas in
 * floating point; only the order of a few sums differs from numpy's pairwise ones); 1e-9
 * relative for log densities (commons-math3's erf against Optuna's fdlibm port, both ~1e-15,
 * through logs of tail masses down to e^-450). Splits and chosen candidates must be identical.
 */
@Tag("fast")
class TpeReferenceTest {

    private static JsonNode reference;

    @BeforeAll
    static void load() throws IOException {
        try (InputStream in = TpeReferenceTest.class.getResourceAsStream("/tpe/optuna-reference.json")) {
            reference = new ObjectMapper().readTree(in);
        }
        assertEquals("3.6.1", reference.get("optuna").asText());
    }

    @Test
    void gammaAndDefaultWeightsMatchOptuna() {
        JsonNode w = reference.get("weights");
        for (int k = 0; k < w.get("n").size(); k++) {
            int n = w.get("n").get(k).asInt();
            assertEquals(w.get("gamma").get(k).asInt(), TpeSampler.gamma(n), "gamma(" + n + ")");
            assertClose(numbers(w.get("weights").get(k)), TpeSampler.defaultWeights(n), 1e-15, "default_weights(" + n + ")");
        }
    }

    @Test
    void truncatedNormalLogDensitiesMatchOptunaInTheTails() {
        for (JsonNode c : reference.get("truncnorm")) {
            double a = c.get("a").asDouble(), b = c.get("b").asDouble();
            assertClose(new double[] {c.get("logMass").asDouble()}, new double[] {TruncatedNormal.logMass(a, b)}, 1e-9, "log mass [" + a + ", " + b + "]");
            double[] x = numbers(c.get("x")), expected = numbers(c.get("logPdf")), actual = new double[x.length];
            for (int i = 0; i < x.length; i++) {
                actual[i] = TruncatedNormal.logPdf(x[i], a, b, 0, 1);
            }
            assertClose(expected, actual, 1e-9, "log pdf on [" + a + ", " + b + "]");
        }
    }

    @Test
    void hypervolumesMatchOptunasWfg() {
        for (JsonNode c : reference.get("hypervolumes")) {
            double[][] points = matrix(c.get("points"));
            double hv = Hypervolume.of(points, numbers(c.get("reference")));
            assertEquals(c.get("hypervolume").asDouble(), hv, 1e-12 * Math.abs(hv), points.length + " points in " + points[0].length + "-D");
        }
    }

    @Test
    void splitsWeightsEstimatorsAndChoicesMatchOptuna() {
        int estimators = 0;
        for (JsonNode c : reference.get("cases")) {
            String name = c.get("name").asText();
            List<Param> space = new ArrayList<>();
            for (JsonNode p : c.get("space")) {
                space.add(new Param(p.get("name").asText(), p.get("low").asDouble(), p.get("high").asDouble(), p.get("log").asBoolean(), p.get("int").asBoolean()));
            }
            List<Direction> directions = new ArrayList<>();
            for (JsonNode d : c.get("directions")) {
                directions.add(Direction.valueOf(d.asText().toUpperCase(java.util.Locale.ROOT)));
            }
            List<CompletedTrial> history = new ArrayList<>();
            for (JsonNode t : c.get("history")) {
                history.add(new CompletedTrial(t.get("number").asInt(), numbers(t.get("params")), numbers(t.get("values"))));
            }
            JsonNode s = c.get("settings");
            TpeSettings settings = new TpeSettings(10, 24, true, s.has("priorWeight") ? s.get("priorWeight").asDouble() : 1.0, true,
                    s.has("considerEndpoints") && s.get("considerEndpoints").asBoolean());
            TpeSampler sampler = new TpeSampler(space, directions, settings);

            assertEquals(c.get("nBelow").asInt(), TpeSampler.gamma(history.size()), name + ": gamma");
            TpeSampler.Estimators model = sampler.fit(history);
            assertArrayEquals(ints(c.get("below")), numbers(model.split.below()), name + ": below trials");
            assertArrayEquals(ints(c.get("above")), numbers(model.split.above()), name + ": above trials");
            if (c.has("belowHypervolumeWeights")) {
                assertClose(numbers(c.get("belowHypervolumeWeights")), TrialSplit.hypervolumeWeights(model.split.below(), directions), 1e-12,
                        name + ": MOTPE weights of the below trials");
            }
            for (int i = 0; i < space.size(); i++) {
                JsonNode p = c.get("params").get(space.get(i).name());
                String where = name + ", " + space.get(i).name();
                assertEstimator(p.get("below"), model.below[i], space.get(i), where + ", l(x)");
                assertEstimator(p.get("above"), model.above[i], space.get(i), where + ", g(x)");
                double[] candidates = numbers(p.get("candidates"));
                double[] logBelow = new double[candidates.length], logAbove = new double[candidates.length];
                for (int k = 0; k < candidates.length; k++) {
                    logBelow[k] = model.below[i].logPdf(space.get(i).toInternal(candidates[k]));
                    logAbove[k] = model.above[i].logPdf(space.get(i).toInternal(candidates[k]));
                }
                assertClose(numbers(p.get("logPdfBelow")), logBelow, 1e-9, where + ": log l(x) at the candidates");
                assertClose(numbers(p.get("logPdfAbove")), logAbove, 1e-9, where + ": log g(x) at the candidates");
                assertEquals(p.get("chosen").asDouble(), model.best(i, candidates), 0.0, where + ": chosen candidate");
                estimators += 2;
            }
        }
        assertEquals(54, estimators, "every recorded estimator checked");
    }

    private static void assertEstimator(JsonNode expected, ParzenEstimator actual, Param param, String where) {
        assertClose(numbers(expected.get("weights")), actual.weights(), 1e-12, where + ": weights");
        assertClose(numbers(expected.get("mus")), actual.mus(), 1e-12, where + ": means");
        assertClose(numbers(expected.get("sigmas")), actual.sigmas(), 1e-12, where + ": sigmas");
        assertEquals(expected.get("low").asDouble(), param.internalLow(), 0.0, where + ": low");
        assertEquals(expected.get("high").asDouble(), param.internalHigh(), 0.0, where + ": high");
        assertEquals(expected.get("step").asDouble(), param.step(), 0.0, where + ": step");
    }

    static void assertClose(double[] expected, double[] actual, double relative, String what) {
        assertEquals(expected.length, actual.length, what + ": length");
        for (int i = 0; i < expected.length; i++) {
            double tol = relative * Math.max(1, Math.abs(expected[i]));
            assertTrue(Math.abs(expected[i] - actual[i]) <= tol || expected[i] == actual[i],
                    what + " [" + i + "]: expected " + expected[i] + ", got " + actual[i]);
        }
    }

    private static double[] numbers(JsonNode array) {
        double[] out = new double[array.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = array.get(i).asDouble();
        }
        return out;
    }

    private static int[] ints(JsonNode array) {
        int[] out = new int[array.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = array.get(i).asInt();
        }
        return out;
    }

    private static int[] numbers(List<CompletedTrial> trials) {
        return trials.stream().mapToInt(CompletedTrial::number).toArray();
    }

    private static double[][] matrix(JsonNode rows) {
        double[][] out = new double[rows.size()][];
        for (int i = 0; i < out.length; i++) {
            out[i] = numbers(rows.get(i));
        }
        return out;
    }
}
