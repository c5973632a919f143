package handsim.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import handsim.app.Main;
import handsim.config.Json;
import handsim.kin.Frame;
import handsim.kin.Kinematics;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.Body;
import handsim.model.Dof;
import handsim.model.HandModel;
import handsim.model.Joint;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The exported BVH, read back by a reader of its own ({@link BvhReader}): its channels give the
 * simulator's joint angles at every sample, the object's root gives the object's pose, and a
 * frame of zero angles puts every joint where {@code handsim info --pose zero} says.
 */
@Tag("slow")
class BvhRoundTripTest {

    /** 1e-6 rad (the bound); the file holds degrees to 6 decimals, 1.7e-8 rad. */
    static final double RADIANS = 1e-6;
    /** Positions are written to 7 decimals of a metre: 5e-8 m each, a few along a chain. */
    static final double METRES = 1e-6;

    static RecordedRun run;
    static BvhReader bvh;
    @TempDir
    static Path dir;

    @BeforeAll
    static void record() throws Exception {
        run = new RecordedRun("can", 3, 2.0, 60, 1.2);
        Path file = dir.resolve("run.bvh");
        ExportTarget.of(file, "bvh", "--out", "--format").write(run.clip, null);
        bvh = BvhReader.read(file);
    }

    @Test
    void theChannelsGiveTheSimulatorsJointAnglesAtEverySample() {
        HandModel model = run.clip.model();
        Kinematics kin = new Kinematics(model);
        assertEquals(run.clip.samples().size(), bvh.frames.size(), "one frame per sample");
        assertEquals(1 / 60.0, bvh.frameTime, 1e-9);
        double worst = 0, worstChannel = 0;
        for (int f = 0; f < bvh.frames.size(); f++) {
            double[] simulated = run.jointAngles.get(f);
            for (Body b : model.bodies()) {
                BvhReader.Joint j = bvh.joints.get(b.name());
                Joint joint = model.joints().get(b.joint());
                // the channels' rotation, split into the joint's DOF angles as the simulator reads them
                double[] q = new double[model.dofCount()];
                kin.decompose(joint, bvh.rotation(j, bvh.frames.get(f)), q);
                for (int d = joint.firstDof(); d < joint.firstDof() + joint.dofCount(); d++) {
                    worst = Math.max(worst, Math.abs(q[d] - simulated[d]));
                    Dof dof = model.dofs().get(d);
                    int axis = dominant(dof.axis());
                    if (Math.abs(Math.abs(dof.axis().get(axis)) - 1) < 1e-12) {
                        // a DOF about a coordinate axis is that axis's channel, signed as the axis
                        double channel = Math.toRadians(bvh.value(j, "XYZ".charAt(axis) + "rotation", f));
                        worstChannel = Math.max(worstChannel, Math.abs(channel - Math.signum(dof.axis().get(axis)) * simulated[d]));
                    }
                }
            }
        }
        System.out.printf("bvh: largest joint angle error %.2e rad, channel error %.2e rad over %d frames%n", worst, worstChannel,
                bvh.frames.size());
        assertTrue(worst <= RADIANS, "largest joint angle error " + worst + " rad");
        assertTrue(worstChannel <= RADIANS, "largest error of a DOF's own channel " + worstChannel + " rad");
    }

    @Test
    void theChannelsFollowTheModelsEulerOrder() {
        // the shoulder's DOFs turn about -x, -z, +y in that order; the wrist's about y, -x, -z
        assertEquals(java.util.List.of("Xrotation", "Zrotation", "Yrotation"), bvh.joints.get("upper_arm").channels());
        assertEquals(java.util.List.of("Yrotation", "Xrotation", "Zrotation"), bvh.joints.get("palm").channels());
        assertEquals(java.util.List.of("Xposition", "Yposition", "Zposition", "Xrotation", "Yrotation", "Zrotation"),
                bvh.joints.get("can").channels(), "the object: a second root with 6 channels");
        assertEquals(-1, bvh.joints.get("can").parent());
    }

    @Test
    void theObjectsRootFollowsTheObject() {
        double worstMetres = 0, worstRadians = 0;
        BvhReader.Joint can = bvh.joints.get("can");
        for (int f = 0; f < bvh.frames.size(); f++) {
            Frame want = run.clip.samples().get(f).objectFrame(), got = bvh.world(can, f);
            worstMetres = Math.max(worstMetres, want.origin().distance(got.origin()));
            worstRadians = Math.max(worstRadians, want.rotation().angleTo(got.rotation()));
        }
        assertTrue(worstMetres <= METRES, "object position error " + worstMetres + " m");
        assertTrue(worstRadians <= RADIANS, "object rotation error " + worstRadians + " rad");
    }

    @Test
    void aZeroAngleFramePutsEveryJointWhereInfoSays() throws Exception {
        Path json = dir.resolve("info.json");
        PrintStream stdout = System.out;
        try {
            System.setOut(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
            assertEquals(0, Main.run("info", "--pose", "zero", "--json", json.toString()));
        } finally {
            System.setOut(stdout);
        }
        Map<String, Vec3> origins = new HashMap<>();
        for (JsonNode b : Json.load(json).node().get("pose").get("bodies")) {
            JsonNode o = b.get("origin");
            origins.put(b.get("name").asText(), new Vec3(o.get(0).asDouble(), o.get(1).asDouble(), o.get(2).asDouble()));
        }
        assertEquals(run.clip.model().bodyCount(), origins.size());
        for (Body b : run.clip.model().bodies()) {
            Frame zero = bvh.world(bvh.joints.get(b.name()), -1);
            assertEquals(0, zero.origin().distance(origins.get(b.name())), METRES, b.name() + " at rest");
            assertEquals(0, zero.rotation().angleTo(Quat.IDENTITY), 1e-12, "every frame aligned with the world at rest");
        }
        Optional.ofNullable(bvh.joints.get("upper_arm")).ifPresent(j -> assertEquals(-1, j.parent(), "the arm's root"));
    }

    private static int dominant(Vec3 a) {
        int k = 0;
        for (int i = 1; i < 3; i++) {
            k = Math.abs(a.get(i)) > Math.abs(a.get(k)) ? i : k;
        }
        return k;
    }
}
