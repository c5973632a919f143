package handsim.train;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.ControllerConfig;
import handsim.learn.Policy;
import handsim.task.HeightGoals;
import handsim.task.StateVector;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Throw policy files: a save-load round trip acts identically; a policy is refused for what it was not trained for. */
@Tag("fast")
class ThrowPolicyFileTest {

    private final ControllerConfig cc = ControllerConfig.load(Home.resolve("configs/controller.json"));

    /** A small random actor for the height task's state (13 entries) and 7 actions. */
    static Policy randomActor(int inputs, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        double[][] w1 = new double[8][inputs], w2 = new double[7][8];
        for (double[] row : w1) {
            for (int i = 0; i < row.length; i++) {
                row[i] = r.nextDouble() - 0.5;
            }
        }
        for (double[] row : w2) {
            for (int i = 0; i < row.length; i++) {
                row[i] = r.nextDouble() - 0.5;
            }
        }
        double[] mean = new double[inputs], std = new double[inputs];
        java.util.Arrays.fill(std, 0.5);
        return new Policy(mean, std, 5, List.of(new Policy.Layer(w1, new double[8], Policy.Activation.RELU),
                new Policy.Layer(w2, new double[7], Policy.Activation.TANH)), "test actor", "test");
    }

    @Test
    void saveThenLoadGivesIdenticalActions(@TempDir Path dir) throws Exception {
        ThrowPolicyFile f = new ThrowPolicyFile("height", "sphere", StateVector.Encoding.PAPER, cc.throwSpace(), randomActor(StateVector.Encoding.PAPER.baseSize() + 1, 5),
                Json.mapper().createObjectNode().put("run", "test"));
        f.save(dir.resolve("p.json"));
        ThrowPolicyFile back = ThrowPolicyFile.load(dir.resolve("p.json"));
        SplittableRandom r = new SplittableRandom(9);
        for (int k = 0; k < 20; k++) {
            double[] s = new double[StateVector.Encoding.PAPER.baseSize() + 1];
            for (int i = 0; i < s.length; i++) {
                s[i] = 2 * r.nextDouble() - 1;
            }
            assertArrayEquals(f.policy().act(s), back.policy().act(s), 0, "bit-identical actions");
        }
        assertArrayEquals(cc.throwSpace().low(), back.space().low(), 0);
        assertArrayEquals(cc.throwSpace().high(), back.space().high(), 0);
    }

    @Test
    void aPolicyIsRefusedForAnotherTaskOrObject() {
        ThrowPolicyFile f = new ThrowPolicyFile("height", "sphere", StateVector.Encoding.PAPER, cc.throwSpace(), randomActor(StateVector.Encoding.PAPER.baseSize() + 1, 5),
                Json.mapper().createObjectNode());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> f.forTask(TestSupport.heightTask(HeightGoals.fixed(1.2)), TestSupport.object("can")));
        assertTrue(e.getMessage().contains("sphere") && e.getMessage().contains("can"), e.getMessage());
        ThrowPolicyFile wrongSize = new ThrowPolicyFile("height", "sphere", StateVector.Encoding.PAPER, cc.throwSpace(), randomActor(15, 5),
                Json.mapper().createObjectNode());
        e = assertThrows(IllegalArgumentException.class, () -> wrongSize.forTask(TestSupport.heightTask(HeightGoals.fixed(1.2)), TestSupport.object("sphere")));
        assertTrue(e.getMessage().contains("15"), e.getMessage());
    }

    @Test
    void aMalformedFileNamesTheField(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("bad.json");
        Files.writeString(file, "{\"format\": \"handsim-throw-policy\", \"task\": \"height\", \"object\": \"sphere\", "
                + "\"throwSpace\": {\"low\": [0, 0, 0, 0, 0, 0, 0], \"high\": [1, 1, 1, 1, 1, 1]}, \"provenance\": {}, \"policy\": {}}");
        ConfigException e = assertThrows(ConfigException.class, () -> ThrowPolicyFile.load(file));
        assertTrue(e.getMessage().contains("throwSpace.high"), e.getMessage());
    }

    /**
     * A rest policy (trained by a DAgger run with learnerThrows.rest) makes the later throws from
     * that rest and no others, read from the decision's observation (Rest.at); a file
     * naming no known rest is refused as the rest policy's.
     */
    @Test
    void aRestPolicyMakesTheLaterThrowsFromItsRestAlone(@TempDir Path dir) throws Exception {
        handsim.task.ThrowTask flip = TestSupport.configs().flip().newTask("can");
        handsim.sim.ObjectSpec can = TestSupport.object("can");
        int n = StateVector.Encoding.CONTINUOUS.baseSize() + flip.goalSize();
        com.fasterxml.jackson.databind.node.ObjectNode provenance = Json.mapper().createObjectNode();
        provenance.putObject("config").putObject("learnerThrows").put("rest", "flat_askew");
        ThrowPolicyFile usual = new ThrowPolicyFile("flip", "can", StateVector.Encoding.CONTINUOUS, flip.throwSpace(cc.throwSpace()),
                randomActor(n, 5), Json.mapper().createObjectNode());
        ThrowPolicyFile rest = new ThrowPolicyFile("flip", "can", StateVector.Encoding.CONTINUOUS, flip.throwSpace(cc.throwSpace()),
                randomActor(n, 6), provenance);
        assertEquals(handsim.task.Rest.FLAT_ASKEW, rest.restServed());
        handsim.control.ThrowPolicy both = ThrowPolicyFile.throwPolicy(usual, null, null, rest, dir.resolve("rest.json"), flip, can, null);
        handsim.math.Vec3 axis = can.longAxis().orElseThrow();
        for (double headingDeg : new double[] {2, 20}) { // flat (3 deg out of the palm's plane), across / askew
            double tilt = Math.toRadians(3), heading = Math.toRadians(headingDeg);
            handsim.math.Vec3 inPalm = new handsim.math.Vec3(Math.cos(tilt) * Math.sin(heading), Math.sin(tilt),
                    Math.cos(tilt) * Math.cos(heading));
            handsim.control.Observation at = new handsim.control.Observation(0, new double[0], new double[0],
                    handsim.kin.Frame.IDENTITY, handsim.math.Vec3.ZERO, new handsim.sim.RigidState(new handsim.math.Vec3(0, 0.03, 0),
                            handsim.math.Quat.between(axis, inPalm), handsim.math.Vec3.ZERO, handsim.math.Vec3.ZERO), 0);
            ThrowPolicyFile expected = headingDeg >= 5 ? rest : usual;
            assertEquals(expected.forTask(flip, can).decide(at), both.decide(at, 2), "throw 2 at heading " + headingDeg);
            assertEquals(usual.forTask(flip, can).decide(at), both.decide(at, 1), "the first throw is never the rest policy's");
        }
        provenance.with("config").with("learnerThrows").put("rest", "sideways");
        new ThrowPolicyFile("flip", "can", StateVector.Encoding.CONTINUOUS, flip.throwSpace(cc.throwSpace()), randomActor(n, 6), provenance)
                .save(dir.resolve("bad.json"));
        ConfigException e = assertThrows(ConfigException.class, () -> ThrowPolicyFile.loadRest(dir.resolve("bad.json")));
        assertTrue(e.getMessage().contains("rest policy") && e.getMessage().contains("sideways"), e.getMessage());
    }
}
