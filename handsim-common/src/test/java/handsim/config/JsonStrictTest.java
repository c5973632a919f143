package handsim.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** Every JSON file handsim reads is strict: a key given twice is an error, named with its line and column. */
@Tag("fast")
class JsonStrictTest {

    @Test
    void aKeyGivenTwiceInOneObjectIsRefused() {
        ConfigException e = assertThrows(ConfigException.class, () -> Json.parse("sim.json", "{\n  \"timeStep\": 0.0002,\n"
                + "  \"timeStep\": 0.002\n}"));
        // Jackson reports where the second key ends: line 3, column 13
        assertEquals("sim.json: not valid JSON at line 3, column 13: the key \"timeStep\" appears twice in one object (which one is "
                + "meant?)", e.getMessage());
        assertThrows(ConfigException.class, () -> Json.parse("p.json", "{\"a\": {\"b\": 1, \"b\": 1}}"), "in a nested object too");
        assertEquals(2, Json.parse("ok.json", "{\"a\": {\"b\": 1}, \"b\": 2}").number("b"), 0.0, "one key per object is fine");
    }
}
