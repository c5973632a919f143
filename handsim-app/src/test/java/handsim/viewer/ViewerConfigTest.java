package handsim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.AppTestSupport;
import handsim.TestSupport;
import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.config.Json;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("fast")
class ViewerConfigTest {

    @Test
    void theShippedConfigLoadsWithRealTimeFirst() {
        ViewerConfig c = AppTestSupport.viewerConfig();
        assertEquals(1.0, c.pacing().slowMotion().get(0), "S starts from real time");
        assertEquals(1.0, c.stage().light().norm(), 1e-12);
        assertEquals(3, c.colours().axes().size());
    }

    private static String failure(String path, Object value) {
        ObjectNode root = (ObjectNode) Json.load(Home.resolve("configs/viewer.json")).node().deepCopy();
        String[] parts = path.split("\\.");
        ObjectNode parent = (ObjectNode) root.get(parts[0]);
        parent.set(parts[1], Json.mapper().valueToTree(value));
        return assertThrows(ConfigException.class, () -> ViewerConfig.parse(Json.of("viewer.json", root))).getMessage();
    }

    @Test
    void badValuesAreRejectedNamingTheFieldAndValue() {
        String m = failure("colours.object", new double[] {1, 0.5, 2, 1});
        assertTrue(m.contains("colours.object") && m.contains("2.0"), m);
        m = failure("pacing.maxLagSeconds", 0);
        assertTrue(m.contains("pacing.maxLagSeconds") && m.contains("0"), m);
        m = failure("scene.light", new double[] {0, 1, 0});
        assertTrue(m.contains("scene.light") && m.contains("downward"), m);
        m = failure("window.widht", 100);
        assertTrue(m.contains("window.widht") && m.contains("unknown field"), m);
    }
}
