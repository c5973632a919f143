package handsim.control;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.TestSupport;
import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.config.Json;
import handsim.math.Vec3;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The controller config's per-object grasps: lookup, and errors that name the field. */
@Tag("fast")
class ControllerConfigTest {

    private static ObjectNode shipped() {
        return (ObjectNode) Json.load(Home.resolve("configs/controller.json")).node().deepCopy();
    }

    private static ControllerConfig parse(ObjectNode node) {
        return ControllerConfig.parse(Json.of("controller.json", node));
    }

    @Test
    void objectsWithoutTheirOwnGraspUseTheDefault() {
        Grasp.Table grasps = parse(shipped()).grasps();
        assertEquals(grasps.forObject("default"), grasps.forObject("no-such-object"));
        assertEquals("open_long", grasps.forObject("can").openPose());
    }

    @Test
    void aMissingDefaultGraspIsNamed() {
        ObjectNode node = shipped();
        ((ObjectNode) node.get("grasps")).remove("default");
        ConfigException e = assertThrows(ConfigException.class, () -> parse(node));
        assertTrue(e.getMessage().contains("grasps.default"), e.getMessage());
    }

    @Test
    void aCatchOffsetOffTheHandIsNamed() {
        ObjectNode node = shipped();
        ((ObjectNode) node.get("grasps").get("can")).set("catchOffset", Json.array(0.3, 0, 0));
        ConfigException e = assertThrows(ConfigException.class, () -> parse(node));
        assertTrue(e.getMessage().contains("grasps.can.catchOffset"), e.getMessage());
    }

    @Test
    void aGraspNamingAnUnknownPoseFailsWhenTheControllerIsBuilt() {
        ObjectNode node = shipped();
        ((ObjectNode) node.get("grasps").get("can")).put("closedPose", "fist");
        ControllerConfig config = parse(node);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new NominalController(
                TestSupport.model(), config, TestSupport.object("can"), new Vec3(0, -9.81, 0)));
        assertTrue(e.getMessage().contains("grasp of can") && e.getMessage().contains("fist"), e.getMessage());
    }
}
