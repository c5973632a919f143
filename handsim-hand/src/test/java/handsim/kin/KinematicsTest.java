package handsim.kin;

import static org.junit.jupiter.api.Assertions.assertEquals;

import handsim.TestSupport;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.model.Joint;
import handsim.model.Site;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("fast")
class KinematicsTest {

    private final HandModel m = TestSupport.model();
    private final Kinematics kin = new Kinematics(m);

    @Test
    void decompositionInvertsTheJointRotationForEveryJoint() {
        SplittableRandom rng = new SplittableRandom(7);
        for (int trial = 0; trial < 200; trial++) {
            double[] q = TestSupport.randomPose(m, rng, 0.01);
            double[] back = new double[q.length];
            for (Joint j : m.joints()) {
                kin.decompose(j, kin.jointRotation(j, q), back);
            }
            for (int i = 0; i < q.length; i++) {
                // exact up to round-off of a few quaternion products
                assertEquals(q[i], back[i], 1e-9, m.dofs().get(i).name());
            }
        }
    }

    @Test
    void ratesRecoverAngleVelocities() {
        SplittableRandom rng = new SplittableRandom(8);
        double dt = 1e-7;
        for (int trial = 0; trial < 50; trial++) {
            double[] q = TestSupport.randomPose(m, rng, 0.05);
            double[] qdot = new double[q.length];
            for (int i = 0; i < q.length; i++) {
                qdot[i] = 2 * rng.nextDouble() - 1;
            }
            double[] q2 = q.clone();
            for (int i = 0; i < q.length; i++) {
                q2[i] += qdot[i] * dt;
            }
            double[] rates = new double[q.length];
            for (Joint j : m.joints()) {
                // relative angular velocity in the parent frame from two nearby joint rotations
                Quat r1 = kin.jointRotation(j, q), r2 = kin.jointRotation(j, q2);
                Vec3 omega = r2.mul(r1.conjugate()).toRotationVector().times(1 / dt);
                kin.rates(j, q, omega, rates);
            }
            for (int i = 0; i < q.length; i++) {
                // forward-difference error ~ dt * |qdot|^2
                assertEquals(qdot[i], rates[i], 1e-5, m.dofs().get(i).name());
            }
        }
    }

    @Test
    void siteJacobianMatchesFiniteDifferences() {
        SplittableRandom rng = new SplittableRandom(9);
        Site palm = m.site("palm_center");
        int[] arm = {0, 1, 2, 3, 4, 5, 6};
        double h = 1e-7;
        for (int trial = 0; trial < 20; trial++) {
            double[] q = TestSupport.randomPose(m, rng, 0.05);
            double[] jac = new double[6 * arm.length];
            kin.siteJacobian(palm, q, arm, jac);
            Frame f0 = kin.siteFrame(palm, q);
            for (int c = 0; c < arm.length; c++) {
                double[] q2 = q.clone();
                q2[arm[c]] += h;
                Frame f1 = kin.siteFrame(palm, q2);
                Vec3 dp = f1.origin().minus(f0.origin()).times(1 / h);
                Vec3 dw = f1.rotation().mul(f0.rotation().conjugate()).toRotationVector().times(1 / h);
                double[] col = {dp.x(), dp.y(), dp.z(), dw.x(), dw.y(), dw.z()};
                for (int r = 0; r < 6; r++) {
                    // forward difference: error ~ h * |second derivative| < 1e-6
                    assertEquals(col[r], jac[r * arm.length + c], 1e-5, "row " + r + " dof " + arm[c]);
                }
            }
        }
    }

    @Test
    void zeroConfigurationPutsBodiesAtTheirAnchors() {
        Frame[] frames = kin.forward(new double[m.dofCount()]);
        for (var b : m.bodies()) {
            assertEquals(0, frames[b.index()].origin().distance(b.origin()), 1e-12);
            assertEquals(0, frames[b.index()].rotation().angleTo(Quat.IDENTITY), 1e-12);
        }
    }

    /**
     * Kinematics.remainder stands in for Math.IEEEremainder(a, 2 pi) in every joint angle read
     * back, so it must give its bits: random angles across 5 turns, and the edges of its fast
     * path (0, pi, 2 pi, each side of them, of both signs) and the values it passes on.
     */
    @Test
    void remainderGivesTheIeeeRemaindersBits() {
        double p = 2 * Math.PI;
        java.util.List<Double> cases = new java.util.ArrayList<>();
        for (double edge : new double[] {0, Math.PI, p, 1.5 * p, 2 * p, Double.MIN_VALUE, 1e-300}) {
            for (double v : new double[] {edge, Math.nextUp(edge), Math.nextDown(edge)}) {
                cases.add(v);
                cases.add(-v);
            }
        }
        SplittableRandom rng = new SplittableRandom(11);
        for (int i = 0; i < 200_000; i++) {
            cases.add(rng.nextDouble(-2.5 * p, 2.5 * p));
        }
        for (double a : cases) {
            assertEquals(Double.doubleToRawLongBits(Math.IEEEremainder(a, p)), Double.doubleToRawLongBits(Kinematics.remainder(a)),
                    () -> "remainder(" + a + ")");
        }
        for (double a : new double[] {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY}) {
            assertEquals(Double.isNaN(Math.IEEEremainder(a, p)), Double.isNaN(Kinematics.remainder(a)), () -> "remainder(" + a + ")");
        }
    }
}
