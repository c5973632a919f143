package handsim.kin;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import handsim.TestSupport;
import handsim.math.Quat;
import handsim.model.HandModel;
import handsim.model.Site;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The allocation-free forms (caller-owned buffers, primitive quaternions) compute the same
 * arithmetic as the Frame/Quat forms: the results are equal to the last bit.
 */
@Tag("fast")
class KinematicsBuffersTest {

    private final HandModel m = TestSupport.model();
    private final Kinematics kin = new Kinematics(m);

    @Test
    void bufferFormsEqualTheObjectFormsExactly() {
        SplittableRandom rng = new SplittableRandom(9);
        Site palm = m.site("palm_center");
        int[] dofs = {0, 1, 2, 3, 4, 5, 6};
        double[] work = new double[Kinematics.SITE_WORK];
        for (int trial = 0; trial < 50; trial++) {
            double[] q = TestSupport.randomPose(m, rng, 0.01);
            Frame f = kin.siteFrame(palm, q);
            kin.siteFrameInto(palm, q, work);
            assertArrayEquals(new double[] {f.origin().x(), f.origin().y(), f.origin().z(), f.rotation().w(),
                f.rotation().x(), f.rotation().y(), f.rotation().z()}, java.util.Arrays.copyOf(work, 7), 0.0);
            double[] a = new double[6 * dofs.length], b = new double[6 * dofs.length];
            kin.siteJacobian(palm, q, dofs, a);
            kin.siteJacobian(palm, q, dofs, b, work);
            assertArrayEquals(a, b, 0.0);
            for (var j : m.joints()) {
                Quat r = kin.jointRotation(j, q);
                double[] x = new double[q.length], y = new double[q.length];
                kin.decompose(j, r, x);
                kin.decompose(j, r.w(), r.x(), r.y(), r.z(), y);
                assertArrayEquals(x, y, 0.0, j.name());
                var axes = kin.worldAxes(j, f.rotation(), q);
                double[] p = {f.rotation().w(), f.rotation().x(), f.rotation().y(), f.rotation().z()};
                double[] w = new double[3 * j.dofCount()];
                kin.worldAxes(j, p, 0, q, w, 0);
                for (int s = 0; s < axes.length; s++) {
                    assertEquals(axes[s].x(), w[3 * s], 0.0);
                    assertEquals(axes[s].y(), w[3 * s + 1], 0.0);
                    assertEquals(axes[s].z(), w[3 * s + 2], 0.0);
                }
            }
        }
    }
}
