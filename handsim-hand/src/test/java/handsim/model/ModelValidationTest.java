package handsim.model;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.config.Json;
import java.util.function.Consumer;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** A malformed or inconsistent model fails with a message naming the field and the bad value. */
@Tag("slow")
class ModelValidationTest {

    private static String failure(Consumer<ObjectNode> corrupt) {
        ObjectNode root = (ObjectNode) Json.load(Home.defaultModel()).node().deepCopy();
        corrupt.accept(root);
        ConfigException e = assertThrows(ConfigException.class, () -> ModelLoader.parse(Json.of("bad.json", root)));
        return e.getMessage();
    }

    private static ObjectNode body(ObjectNode root, int i) {
        return (ObjectNode) root.get("bodies").get(i);
    }

    private static void assertMentions(String message, String... parts) {
        for (String p : parts) {
            assertTrue(message.contains(p), "message should mention \"" + p + "\": " + message);
        }
    }

    @Test
    void unknownParent() {
        String msg = failure(r -> body(r, 3).put("parent", "pinky"));
        assertMentions(msg, "bad.json", "bodies[3].parent", "\"pinky\"");
    }

    @Test
    void missingMass() {
        String msg = failure(r -> body(r, 1).remove("mass"));
        assertMentions(msg, "bodies[1].mass", "missing");
    }

    @Test
    void negativeMass() {
        String msg = failure(r -> body(r, 1).put("mass", -1.2));
        assertMentions(msg, "bodies[1].mass", "-1.2");
    }

    @Test
    void thirtyOneDof() {
        // turn the elbow's hinge-plus-wrist into 31 DOF: make the index MCP a hinge
        String msg = failure(r -> {
            ObjectNode joint = (ObjectNode) body(r, 4).get("joint");
            joint.put("type", "hinge");
            ((ArrayNode) joint.get("dofs")).remove(0);
        });
        assertMentions(msg, "dofBreakdown", "31", "32");
    }

    @Test
    void negativeLimitRange() {
        String msg = failure(r -> {
            JsonNode dof = body(r, 1).get("joint").get("dofs").get(0);
            ((ObjectNode) dof).set("rangeDeg", Json.array(150, 0));
        });
        assertMentions(msg, "bodies[1].joint.dofs[0].rangeDeg", "150");
    }

    @Test
    void wrongDofCountForJointType() {
        String msg = failure(r -> ((ObjectNode) body(r, 1).get("joint")).put("type", "universal"));
        assertMentions(msg, "bodies[1].joint.dofs", "universal", "2");
    }

    @Test
    void unknownFieldIsRejected() {
        String msg = failure(r -> body(r, 2).put("mas", 0.3));
        assertMentions(msg, "bodies[2].mas", "unknown field");
    }

    @Test
    void poseOutsideLimits() {
        String msg = failure(r -> ((ObjectNode) r.get("poses").get("neutral")).put("elbow_flexion", 170));
        assertMentions(msg, "poses.neutral.elbow_flexion", "170");
    }

    @Test
    void missingRequiredPose() {
        String msg = failure(r -> ((ObjectNode) r.get("poses")).remove("closed"));
        assertMentions(msg, "poses", "closed");
    }

    @Test
    void syntaxErrorNamesLineAndColumn() {
        ConfigException e = assertThrows(ConfigException.class, () -> Json.parse("x.json", "{\n \"a\": [1, 2,\n}"));
        assertMentions(e.getMessage(), "x.json");
    }
}
