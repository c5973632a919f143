package handsim.cards.tpe;

import static handsim.cards.tpe.TpeReferenceTest.assertClose;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * MOTPE against Optuna 3.6.1 on recorded three-objective histories shaped as Double Lift's
 * (src/test/resources/tpe/optuna-motpe-reference.json, written by optuna_motpe_reference.py beside
 * it): 15 to 300 trials, objective values rounded so that ties occur, independent and
 * multivariate TPE.
 *
 * <p>Tolerances as in {@link TpeReferenceTest}: splits, Pareto fronts and chosen candidates
 * identical; weights, means and bandwidths to 1e-12 relative; hypervolumes to 1e-12 relative;
 * log densities to 1e-9 relative.
 */
@Tag("fast")
class MotpeReferenceTest {

    private static JsonNode reference;

    @BeforeAll
    static void load() throws IOException {
        try (InputStream in = MotpeReferenceTest.class.getResourceAsStream("/tpe/optuna-motpe-reference.json")) {
            reference = new ObjectMapper().readTree(in);
        }
        assertEquals("3.6.1", reference.get("optuna").asText());
    }

    @Test
    void splitsWeightsHypervolumesEstimatorsAndChoicesMatchOptuna() {
        int cases = 0;
        for (JsonNode c : reference.get("cases")) {
            String name = c.get("name").asText();
            List<Param> space = new ArrayList<>();
            for (JsonNode p : c.get("space")) {
                space.add(new Param(p.get("name").asText(), p.get("low").asDouble(), p.get("high").asDouble(), false, false));
            }
            List<Direction> directions = List.of(Direction.MINIMIZE, Direction.MINIMIZE, Direction.MINIMIZE);
            List<CompletedTrial> history = new ArrayList<>();
            for (JsonNode t : c.get("history")) {
                history.add(new CompletedTrial(t.get("number").asInt(), numbers(t.get("params")), numbers(t.get("values"))));
            }
            boolean multivariate = c.get("multivariate").asBoolean();
            TpeSampler sampler = new TpeSampler(space, directions, new TpeSettings(10, 24, true, 1.0, true, false, multivariate));

            assertEquals(c.get("nBelow").asInt(), TpeSampler.gamma(history.size()), name + ": gamma");
            assertArrayEquals(ints(c.get("paretoFront")), Pareto.front(history, directions).stream().mapToInt(CompletedTrial::number).toArray(),
                    name + ": Pareto front");
            TpeSampler.Estimators model = sampler.fit(history);
            assertArrayEquals(ints(c.get("below")), model.split.below().stream().mapToInt(CompletedTrial::number).toArray(), name + ": below");
            assertArrayEquals(ints(c.get("above")), model.split.above().stream().mapToInt(CompletedTrial::number).toArray(), name + ": above");
            assertClose(numbers(c.get("belowHypervolumeWeights")), TrialSplit.hypervolumeWeights(model.split.below(), directions), 1e-12,
                    name + ": MOTPE weights of the below trials");
            double[][] losses = Pareto.losses(model.split.below(), directions);
            double hv = Hypervolume.of(losses, numbers(c.get("belowReference")));
            assertClose(new double[] {c.get("belowHypervolume").asDouble()}, new double[] {hv}, 1e-12, name + ": hypervolume of the below trials");

            for (String side : List.of("below", "above")) {
                JsonNode e = c.get("estimators").get(side);
                ParzenEstimator[] fitted = side.equals("below") ? model.below : model.above;
                for (int i = 0; i < space.size(); i++) {
                    String where = name + ", " + side + ", " + space.get(i).name();
                    assertClose(numbers(e.get("weights")), fitted[i].weights(), 1e-12, where + ": weights");
                    assertClose(numbers(e.get("mus").get(i)), fitted[i].mus(), 1e-12, where + ": means");
                    assertClose(numbers(e.get("sigmas").get(i)), fitted[i].sigmas(), 1e-12, where + ": sigmas");
                }
            }
            double[][] candidates = new double[c.get("candidates").size()][];
            double[] logBelow = new double[candidates.length], logAbove = new double[candidates.length];
            for (int k = 0; k < candidates.length; k++) {
                candidates[k] = numbers(c.get("candidates").get(k));
                logBelow[k] = model.jointLogPdf(true, candidates[k]);
                logAbove[k] = model.jointLogPdf(false, candidates[k]);
            }
            assertClose(numbers(c.get("logPdfBelow")), logBelow, 1e-9, name + ": log l(x) of the joint estimator at the candidates");
            assertClose(numbers(c.get("logPdfAbove")), logAbove, 1e-9, name + ": log g(x) of the joint estimator at the candidates");
            assertArrayEquals(numbers(c.get("chosen")), model.chooseJoint(candidates), 0.0, name + ": chosen candidate");
            cases++;
        }
        assertEquals(5, cases, "every recorded history checked");
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
}
