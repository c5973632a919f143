package handsim.control;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.Home;
import handsim.kin.Frame;
import handsim.kin.Kinematics;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.model.Site;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * How far the arm can turn the palm about its normal where it catches (the shipped model and
 * controller config): the window of headings {@link CatchPlanner} searches in. A launched can
 * comes at any heading; one outside this window is met, and comes to rest, askew in the palm
 * (docs/experiments.md, "The first throw").
 */
@Tag("fast")
class PalmHeadingReachTest {

    private final HandModel model = TestSupport.model();
    private final Kinematics kin = new Kinematics(model);
    private final Site palm = model.site("palm_center");
    private final ControllerConfig config = ControllerConfig.load(Home.resolve("configs/controller.json"));
    private final DlsIk ik = new DlsIk(kin, palm, config.ik());
    private final double[] neutral = model.poseVector("neutral");
    private final Frame neutralPalm = kin.siteFrame(palm, neutral);

    @Test
    void thePalmTurnsAboutItsNormalOnlyWithinTheWristAndShoulderLimits() {
        // measured from the neutral pose with 400 IK iterations (DlsIkTest's count): reached from
        // -30 to +40 deg; at -50 the forearm is at its supination limit (wrist_pronation -10 deg)
        // and the wrist at its ulnar deviation limit (-30), at +60 the shoulder at its adduction
        // limit (shoulder_abduction -30) and the wrist at its radial deviation limit (+20)
        for (int deg = -30; deg <= 40; deg += 10) {
            assertTrue(reached(deg), "a palm turned " + deg + " deg about its normal is reached");
        }
        for (int deg : new int[] {-90, -70, -50, 60, 70, 90}) {
            assertFalse(reached(deg), "a palm turned " + deg + " deg about its normal is out of reach");
        }
    }

    /**
     * Whether the palm, at the interception height above the neutral palm centre and turned
     * {@code deg} about its normal, is reached within the catch planner's tolerances.
     */
    private boolean reached(int deg) {
        Quat turned = neutralPalm.rotation().mul(Quat.fromAxisAngle(Vec3.Y, Math.toRadians(deg)));
        Vec3 at = new Vec3(neutralPalm.origin().x(), config.interceptionHeight(), neutralPalm.origin().z());
        DlsIk.Residual r = ik.solve(neutral.clone(), new Frame(at, turned), 400);
        CatchPlanner.HeadingSearch tolerances = config.headingSearch();
        return r.position() <= tolerances.positionTolerance() && r.rotation() <= tolerances.rotationTolerance();
    }
}
