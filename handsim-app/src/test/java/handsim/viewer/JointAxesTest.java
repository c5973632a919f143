package handsim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;

import handsim.TestSupport;
import handsim.kin.Frame;
import handsim.kin.Kinematics;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.model.Joint;
import handsim.sim.WorldSnapshot;
import java.util.List;
import java.util.Optional;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The joint-axis overlay recovers every DOF's world axis from body frames alone. */
@Tag("fast")
class JointAxesTest {

    /** Euler decomposition and recomposition in double precision. */
    static final double AXIS_TOLERANCE = 1e-9;

    @Test
    void axesFromFramesMatchTheKinematicsOfTheJointAngles() {
        HandModel model = TestSupport.model();
        Kinematics kin = new Kinematics(model);
        JointAxes overlay = new JointAxes(model);
        SplittableRandom rng = new SplittableRandom(4);
        for (int trial = 0; trial < 20; trial++) {
            double[] q = TestSupport.randomPose(model, rng, 0.05);
            Frame[] frames = kin.forward(q);
            WorldSnapshot snap = new WorldSnapshot(model, 0, List.of(frames), Optional.empty(), Optional.empty(), List.of(), 0);
            List<JointAxes.Axis> axes = overlay.compute(snap);
            assertEquals(model.dofCount(), axes.size());
            int i = 0;
            for (Joint j : model.joints()) {
                var parent = j.isRoot() ? handsim.math.Quat.IDENTITY : frames[j.parent()].rotation();
                Vec3[] want = kin.worldAxes(j, parent, q);
                for (int s = 0; s < want.length; s++, i++) {
                    JointAxes.Axis a = axes.get(i);
                    assertEquals(s, a.slot());
                    assertEquals(0, a.direction().distance(want[s]), AXIS_TOLERANCE, j.name() + " axis " + s);
                    assertEquals(0, a.anchor().distance(frames[j.child()].origin()), AXIS_TOLERANCE, "drawn from the joint");
                }
            }
        }
    }
}
