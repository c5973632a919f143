package handsim.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import handsim.TestSupport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("fast")
class SimConfigTest {

    @Test
    void paperValues() {
        SimConfig c = TestSupport.simConfig();
        assertEquals(0.0002, c.timeStep(), 0);
        assertEquals(5e4, c.contactStiffness(), 0);
        assertEquals(0.01, c.linearDampingPerSecond(), 0);
        assertEquals(0.03, c.angularDampingPerSecond(), 0);
    }

    @Test
    void erpAndCfmFollowSection41() {
        SimConfig c = TestSupport.simConfig();
        double m1 = 0.1, m2 = 0.012, h = 0.0002, kp = 5e4;
        double kd = 2 * Math.sqrt(kp * (m1 + m2));
        assertEquals(kd, c.contactDamping(m1, m2), 1e-12);
        assertEquals(h * kp / (h * kp + kd), c.contactErp(m1, m2), 1e-15);
        assertEquals(1 / (h * kp + kd), c.contactCfm(m1, m2), 1e-15);
        // ODE's soft constraint with this ERP and CFM is a spring kp and damper kd:
        // kp = ERP / (h CFM), kd = (1 - ERP) / CFM
        assertEquals(kp, c.contactErp(m1, m2) / (h * c.contactCfm(m1, m2)), 1e-6);
        assertEquals(kd, (1 - c.contactErp(m1, m2)) / c.contactCfm(m1, m2), 1e-9);
    }
}
