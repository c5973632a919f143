package handsim.evaluation;

import handsim.task.LoopRecord;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.math.Vec3;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The launch-sensitivity figures on hand-computed examples. */
@Tag("fast")
class LaunchSensitivityTest {

    private static LoopRecord loop(int index, double apex, double rotationDeg) {
        return new LoopRecord(index, true, apex, null, Double.NaN, null, false, Double.NaN, Math.toRadians(rotationDeg), Double.NaN,
                Double.NaN, Double.NaN, null, Double.NaN, 0, 0, 0, 1);
    }

    private static final LoopRecord THROW_IN = loop(0, Double.NaN, Double.NaN);

    @Test
    void copyZeroIsTheSeededEpisodeAndTheOthersAreNudgedByTheGivenSpeed() {
        List<Vec3> n = LaunchSensitivity.nudges(7, 5, 1e-9);
        assertEquals(5, n.size());
        assertEquals(Vec3.ZERO, n.get(0));
        for (Vec3 v : n.subList(1, 5)) {
            assertEquals(1e-9, v.norm(), 1e-21);
        }
        assertTrue(n.get(1).distance(n.get(2)) > 1e-10, "random directions");
        assertEquals(n, LaunchSensitivity.nudges(7, 5, 1e-9), "the same seed, the same nudges");
        assertThrows(IllegalArgumentException.class, () -> LaunchSensitivity.nudges(7, 1, 1e-9));
        assertThrows(IllegalArgumentException.class, () -> LaunchSensitivity.nudges(7, 3, 0));
    }

    private static LoopRecord aimed(int index, boolean caught, double apex, double target) {
        return new LoopRecord(index, caught, apex, null, target, null, false, Double.NaN, Double.NaN, Double.NaN, Double.NaN,
                Double.NaN, null, Double.NaN, 0, 0, 0, 1);
    }

    @Test
    void aCopysFiguresAreItsThrowsDropsAndMeanHeightError() {
        // throws 1-3 miss by +0.02, -0.04 and -0.09 m (mean |error| 0.05 m); throw 3 is dropped after its apex
        LaunchSensitivity.CopyFigures f = LaunchSensitivity.CopyFigures.of(3, List.of(THROW_IN, aimed(1, true, 1.02, 1.0),
                aimed(2, true, 0.76, 0.8), aimed(3, false, 1.11, 1.2)));
        assertEquals(3, f.copy());
        assertEquals(3, f.throwsMade());
        assertEquals(1, f.drops());
        assertEquals(0.05, f.heightAbsError(), 1e-12);
        assertTrue(Double.isNaN(LaunchSensitivity.CopyFigures.of(0, List.of(THROW_IN, loop(1, 1.0, 90))).heightAbsError()),
                "no height targets, no height error");
    }

    @Test
    void spreadOfEachThrowOverTheCopiesThatMadeIt() {
        // throw 1: apexes 1.0, 1.2 (sample sd 0.1414), rotations 180, 200 (sd 14.14 deg, range 20);
        // throw 2 only made by the first copy (the second dropped): one value, no spread
        List<List<LoopRecord>> copies = List.of(
                List.of(THROW_IN, loop(1, 1.0, 180), loop(2, 1.1, 90)),
                List.of(THROW_IN, loop(1, 1.2, 200)));
        List<LaunchSensitivity.Spread> s = LaunchSensitivity.spreads(copies);
        assertEquals(2, s.size());
        assertEquals(1, s.get(0).throwIndex());
        assertEquals(2, s.get(0).copies());
        assertEquals(Math.sqrt(0.02), s.get(0).apexSd(), 1e-12);
        assertEquals(Math.toRadians(Math.sqrt(200)), s.get(0).rotationSd(), 1e-12);
        assertEquals(Math.toRadians(20), s.get(0).rotationRange(), 1e-12);
        assertEquals(1, s.get(1).copies());
        assertTrue(Double.isNaN(s.get(1).apexSd()) && Double.isNaN(s.get(1).rotationSd()));
    }

    @Test
    void aSphereHasNoRotationSpreadAndTheMeanSkipsWhatWasNotMeasured() {
        List<LaunchSensitivity.Spread> sphere = LaunchSensitivity.spreads(List.of(
                List.of(THROW_IN, loop(1, 1.0, Double.NaN)), List.of(THROW_IN, loop(1, 1.0, Double.NaN))));
        assertEquals(0, sphere.get(0).apexSd(), 0, "identical copies");
        assertTrue(Double.isNaN(sphere.get(0).rotationSd()));
        // episode A: throw 1 sd 0.2, throw 2 sd 0.4; episode B: throw 1 sd 0.6, no throw 2
        List<LaunchSensitivity.Spread> a = List.of(new LaunchSensitivity.Spread(1, 3, 0.2, 0.1, 0.3),
                new LaunchSensitivity.Spread(2, 2, 0.4, Double.NaN, Double.NaN));
        List<LaunchSensitivity.Spread> b = List.of(new LaunchSensitivity.Spread(1, 3, 0.6, 0.3, 0.5));
        List<LaunchSensitivity.Spread> m = LaunchSensitivity.mean(List.of(a, b));
        assertEquals(2, m.size());
        assertEquals(0.4, m.get(0).apexSd(), 1e-12);
        assertEquals(0.2, m.get(0).rotationSd(), 1e-12);
        assertEquals(0.4, m.get(0).rotationRange(), 1e-12);
        assertEquals(6, m.get(0).copies());
        assertEquals(0.4, m.get(1).apexSd(), 1e-12);
        assertEquals(2, m.get(1).copies());
        assertTrue(Double.isNaN(m.get(1).rotationSd()));
        // medians: a third episode that jumps moves the mean of throw 1's apex spread to 33.6, the median to 0.6
        List<LaunchSensitivity.Spread> c = List.of(new LaunchSensitivity.Spread(1, 3, 100, 0.2, 0.4));
        assertEquals(33.6, LaunchSensitivity.mean(List.of(a, b, c)).get(0).apexSd(), 1e-12);
        List<LaunchSensitivity.Spread> med = LaunchSensitivity.median(List.of(a, b, c));
        assertEquals(0.6, med.get(0).apexSd(), 1e-12);
        assertEquals(0.2, med.get(0).rotationSd(), 1e-12);
        assertEquals(0.4, med.get(0).rotationRange(), 1e-12);
        assertEquals(9, med.get(0).copies());
        assertEquals(0.4, LaunchSensitivity.median(List.of(a, b)).get(0).apexSd(), 1e-12, "an even count: the middle two's mean");
    }
}
