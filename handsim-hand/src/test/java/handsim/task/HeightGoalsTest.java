package handsim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The height goals of an episode: a list is taken in turn, from its start in every episode. */
@Tag("fast")
class HeightGoalsTest {

    @Test
    void aListOfGoalsIsTakenInTurnInEveryEpisode() {
        HeightGoals g = HeightGoals.sequence(new double[] {1.0, 1.3, 1.1});
        g.reset(5);
        double[] seen = new double[4];
        for (int i = 0; i < 4; i++) {
            seen[i] = g.current();
            g.advance();
        }
        org.junit.jupiter.api.Assertions.assertArrayEquals(new double[] {1.0, 1.3, 1.1, 1.0}, seen, 0);
        g.reset(6);
        assertEquals(1.0, g.current(), 0, "a new episode starts the list again");
    }
}
