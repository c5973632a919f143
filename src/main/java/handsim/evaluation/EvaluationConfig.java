package handsim.evaluation;

import handsim.config.Json;
import java.nio.file.Path;

/**
 * {@code configs/evaluation.json}: how {@code handsim evaluate} reports.
 *
 * @param sensitivityThrows throws each copy of a sensitivity run makes by default
 * @param boxBands distance bands of the box summary (equal shares of the region's radius)
 * @param plannedProgressEvery a planned flip episode prints a line every this many loops in a row
 */
public record EvaluationConfig(int sensitivityThrows, int boxBands, int plannedProgressEvery) {

    public static EvaluationConfig load(Path file) {
        Json j = Json.load(file);
        j.allow("comment", "sensitivityThrowsComment", "boxBandsComment", "plannedProgressEveryComment");
        EvaluationConfig c = new EvaluationConfig(j.integer("sensitivityThrows", 0, 100000), j.integer("boxBands", 1, 100),
                j.integer("plannedProgressEvery", 1, 100000));
        j.requireNoUnknownFields();
        return c;
    }
}
