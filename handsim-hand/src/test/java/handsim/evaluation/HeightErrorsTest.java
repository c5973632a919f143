package handsim.evaluation;

import handsim.task.LoopRecord;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The height task's accuracy figures on hand-computed examples. */
@Tag("fast")
class HeightErrorsTest {

    private static LoopRecord loop(int index, double apex, double target) {
        return new LoopRecord(index, true, apex, null, target, null, false, Double.NaN, Double.NaN, Double.NaN, Double.NaN,
                Double.NaN, null, Double.NaN, 0, 0, 0, 1);
    }

    @Test
    void figuresOfTwentyThrows() {
        // errors -0.10, -0.09, ..., +0.09 (20 throws, 1 cm apart) plus loop 0, which is not a throw
        List<LoopRecord> loops = new java.util.ArrayList<>(List.of(loop(0, Double.NaN, Double.NaN)));
        for (int i = 0; i < 20; i++) {
            loops.add(loop(i + 1, 1.2 + (i - 10) * 0.01, 1.2));
        }
        HeightErrors e = HeightErrors.of(loops);
        assertEquals(20, e.count());
        assertEquals(-0.005, e.mean(), 1e-12, "mean of -0.10 .. +0.09");
        assertEquals(0.05, e.absMean(), 1e-12, "(0.10 + 2 (0.01 + ... + 0.09)) / 20 = 1.0 / 20");
        // |errors| sorted: 0, .01, .01, ..., .09, .09, .10; nearest rank ceil(0.95 * 20) = 19 -> 0.09
        assertEquals(0.09, e.absP95(), 1e-12);
        assertEquals(20 / 20.0, e.within(0.1 + 1e-12), 1e-12);
        assertEquals(19 / 20.0, e.within(0.095), 1e-12, "all but the -0.10 throw");
    }
}
