package handsim.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("fast")
class PairedLoopsTest {

    @Test
    void theDifferenceIsTakenSeedBySeedOnTheSeedsBothRan() {
        // A: seeds 1-4 and 9; B: seeds 1-4 and 7. Shared 1-4 with B - A = 0, +100, -6, 0: mean 23.5; sample
        // variance (0 + 100^2 + 6^2 + 0 - 4 * 23.5^2) / 3 = 2609, standard error sqrt(2609 / 4) = 25.539 (by hand)
        PairedLoops p = PairedLoops.of(Map.of(1L, 100, 2L, 0, 3L, 17, 4L, 5, 9L, 3), Map.of(1L, 100, 2L, 100, 3L, 11, 4L, 5, 7L, 8));
        assertEquals(List.of(1L, 2L, 3L, 4L), p.seeds());
        assertEquals(30.5, p.meanA(), 1e-12);
        assertEquals(54.0, p.meanB(), 1e-12);
        assertEquals(23.5, p.meanDifference(), 1e-12);
        assertEquals(Math.sqrt(2609.0 / 4), p.standardError(), 1e-12);
        assertEquals(List.of(new PairedLoops.Change(2, 0, 100), new PairedLoops.Change(3, 17, 11)), p.changes());
        assertEquals(1, p.better());
        assertEquals(1, p.worse());
        assertEquals(List.of(9L), p.onlyA());
        assertEquals(List.of(7L), p.onlyB());
    }

    @Test
    void identicalEvaluationsDifferByNothingAndDisjointOnesAreRefused() {
        PairedLoops same = PairedLoops.of(Map.of(1L, 3, 2L, 40), Map.of(1L, 3, 2L, 40));
        assertEquals(0, same.meanDifference(), 0);
        assertEquals(0, same.standardError(), 0);
        assertEquals(List.of(), same.changes());
        assertEquals(Double.NaN, PairedLoops.of(Map.of(5L, 1), Map.of(5L, 2)).standardError(), "one seed: no spread to estimate");
        assertThrows(IllegalArgumentException.class, () -> PairedLoops.of(Map.of(1L, 3), Map.of(2L, 3)));
    }
}
