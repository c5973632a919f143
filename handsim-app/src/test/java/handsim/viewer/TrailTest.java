package handsim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import handsim.math.Vec3;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("fast")
class TrailTest {

    @Test
    void keepsTheLastSecondsAndStartsAgainWhenTimeGoesBack() {
        Trail t = new Trail(0.5);
        for (int i = 0; i <= 100; i++) {
            t.add(i * 0.01, new Vec3(i, 0, 0));
        }
        // points from t = 0.5 to 1.0 are within 0.5 s of the newest
        assertEquals(51, t.size());
        assertEquals(0.5, t.time(0), 1e-12);
        t.add(1.0, new Vec3(7, 7, 7));
        assertEquals(51, t.size(), "the same instant twice is one point");
        t.add(0.2, Vec3.ZERO);
        assertEquals(1, t.size(), "a reset starts a new trail");
        assertThrows(IllegalArgumentException.class, () -> new Trail(0));
    }
}
