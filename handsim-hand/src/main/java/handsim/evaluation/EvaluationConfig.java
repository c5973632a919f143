package handsim.evaluation;

import handsim.config.Json;
import java.nio.file.Path;
import java.util.Arrays;

/**
 * {@code configs/evaluation.json}: how {@code handsim evaluate} reports.
 *
 * @param sensitivityThrows throws each copy of a sensitivity run makes by default
 * @param boxBands distance bands of the box summary (equal shares of the region's radius)
 * @param plannedProgressEvery a planned flip episode prints a line every this many loops in a row
 * @param flipBins the bins of the flip summary's counts
 */
public record EvaluationConfig(int sensitivityThrows, int boxBands, int plannedProgressEvery, FlipReport.Bins flipBins) {

    public static EvaluationConfig load(Path file) {
        return parse(Json.load(file));
    }

    public static EvaluationConfig parse(Json j) {
        j.allow("comment", "sensitivityThrowsComment", "boxBandsComment", "plannedProgressEveryComment", "flipBinsComment");
        EvaluationConfig c = new EvaluationConfig(j.integer("sensitivityThrows", 0, 100000), j.integer("boxBands", 1, 100),
                j.integer("plannedProgressEvery", 1, 100000), flipBins(j.get("flipBins")));
        j.requireNoUnknownFields();
        return c;
    }

    private static FlipReport.Bins flipBins(Json j) {
        j.allow("comment");
        double angleBinDeg = j.number("angleBinDeg", 1, 90);
        if (Math.abs(90 / angleBinDeg - Math.round(90 / angleBinDeg)) > 1e-9) {
            throw j.fieldError("angleBinDeg", "must divide 90 deg into whole bins, got " + Json.show(angleBinDeg));
        }
        int earlyThrows = j.integer("earlyThrows", 1, 100000);
        double[] edges = j.numbers("catchDistanceEdges", -1);
        for (int i = 0; i < edges.length; i++) {
            if (!(edges[i] > (i == 0 ? 0 : edges[i - 1]))) {
                throw j.fieldError("catchDistanceEdges", "must rise from above 0 m, got " + Arrays.toString(edges));
            }
        }
        j.requireNoUnknownFields();
        return new FlipReport.Bins(Math.toRadians(angleBinDeg), earlyThrows, edges);
    }
}
