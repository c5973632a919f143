package handsim.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The sim-time accumulator, driven by hand-made wall times. */
@Tag("fast")
class SimClockTest {

    static final double EPS = 1e-12;

    @Test
    void owesWallTimeTimesSpeedAndCarriesOvershoot() {
        SimClock c = new SimClock(0.1);
        assertEquals(1 / 60.0, c.tick(1 / 60.0), EPS, "real time: one frame owes one frame of simulated time");
        c.advanced(0.018); // the scene moved in whole ticks and overshot by 1.33 ms
        assertEquals(2 / 60.0 - 0.018, c.tick(1 / 60.0), EPS, "the overshoot is paid back by the next frame");
        c.setSpeed(0.25);
        c.advanced(2 / 60.0 - 0.018);
        assertEquals(0.25 / 60, c.tick(1 / 60.0), EPS, "slow motion scales the time owed");
    }

    @Test
    void capsTheDebtWhenTheSimulationFallsBehind() {
        // the spiral-of-death guard: a scene that cannot keep up is owed at most maxLag
        SimClock c = new SimClock(0.1);
        assertEquals(0.1, c.tick(0.5), EPS);
        assertEquals(0.4, c.droppedSeconds(), EPS, "the time given up is counted");
        c.advanced(0.05);
        assertEquals(0.1, c.tick(1.0), EPS);
        assertEquals(0.4 + 0.95, c.droppedSeconds(), EPS);
    }

    @Test
    void pauseOwesNothingAndSingleStepsOweExactlyTheStep() {
        SimClock c = new SimClock(0.1);
        c.tick(0.01);
        c.setPaused(true);
        assertEquals(0, c.tick(1.0), EPS, "paused: wall time passes, nothing is owed");
        c.requestStep(0.002);
        assertEquals(0.002, c.tick(1.0), EPS);
        c.advanced(0.002);
        assertEquals(0, c.tick(1.0), EPS, "one step, then still paused");
        c.setPaused(false);
        assertEquals(0.01, c.tick(0.01), EPS, "resuming does not jump by the time spent paused");
    }

    @Test
    void saysWhenTheNextChunkIsDue() {
        SimClock c = new SimClock(0.1);
        c.setSpeed(0.5);
        c.tick(0.002);
        assertEquals((0.004 - 0.001) / 0.5, c.wallSecondsUntilOwed(0.004), EPS, "3 ms more owed at half speed: 6 ms");
        c.tick(0.01);
        assertEquals(0, c.wallSecondsUntilOwed(0.004), EPS);
        c.setPaused(true);
        assertEquals(Double.POSITIVE_INFINITY, c.wallSecondsUntilOwed(0.004));
    }

    @Test
    void rejectsNonsense() {
        SimClock c = new SimClock(0.1);
        assertThrows(IllegalArgumentException.class, () -> c.setSpeed(0));
        assertThrows(IllegalArgumentException.class, () -> c.tick(-1));
        assertThrows(IllegalArgumentException.class, () -> new SimClock(0));
    }
}
