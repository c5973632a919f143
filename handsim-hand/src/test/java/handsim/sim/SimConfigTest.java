package handsim.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.TestSupport;
import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.config.Json;
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

    @Test
    void divergenceLimitsAreReadAndABadOneIsNamed() {
        // configs/sim.json: the object past 200 m/s, an arm body of 0.1 kg or more past 2,000 rad/s
        SimConfig.Divergence d = TestSupport.simConfig().divergence();
        assertEquals(200, d.objectSpeed(), 0);
        assertEquals(2000, d.bodySpin(), 0);
        assertEquals(0.1, d.spinCheckedMass(), 0);
        ObjectNode file = (ObjectNode) Json.load(Home.resolve("configs/sim.json")).node().deepCopy();
        ((ObjectNode) file.get("divergence")).put("bodySpin", -5);
        ConfigException e = assertThrows(ConfigException.class, () -> SimConfig.parse(Json.of("sim.json", file)));
        assertTrue(e.getMessage().contains("divergence.bodySpin") && e.getMessage().contains("-5"), e.getMessage());
    }
}
