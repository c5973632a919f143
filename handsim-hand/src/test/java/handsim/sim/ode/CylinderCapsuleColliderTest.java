package handsim.sim.ode;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.ode4j.math.DMatrix3;
import org.ode4j.ode.DCapsule;
import org.ode4j.ode.DContactGeomBuffer;
import org.ode4j.ode.DCylinder;
import org.ode4j.ode.OdeHelper;

/**
 * The analytic cylinder-capsule contact: exact cases worked by hand, agreement with a brute-force
 * search along the capsule, continuity in the poses, and ODE's normal convention.
 */
@Tag("fast")
class CylinderCapsuleColliderTest {

    // the can: r 0.03, h 0.1, along y at the origin; a finger-sized capsule, r 0.01, 4 cm long
    private static final double R = 0.03, HALF = 0.05, r = 0.01, L = 0.02;
    private static final double[] CAN = {0, 0, 0, 0, 1, 0};
    private static final int C = CylinderCapsuleCollider.CONTACT;

    private final CylinderCapsuleCollider collider = new CylinderCapsuleCollider();
    private final double[] out = new double[2 * C];

    private int collide(double[] capsule) {
        return collider.collide(CAN, R, HALF, capsule, r, L, out, 4);
    }

    @Test
    void capsuleAcrossTheSideTouchesAtOnePoint() {
        // along x, 1 mm into the side at z: the nearest point is the capsule's middle
        assertEquals(1, collide(new double[] {0, 0.01, R + r - 0.001, 1, 0, 0}));
        assertContact(0, 0, 0.01, R - 0.0005, 0, 0, 1, 0.001);
        // shifted 15 mm along its axis: the nearest point moves to s = -0.015, still x = 0
        assertEquals(1, collide(new double[] {0.015, 0.01, R + r - 0.001, 1, 0, 0}));
        assertContact(0, 0, 0.01, R - 0.0005, 0, 0, 1, 0.001);
    }

    @Test
    void capsuleFlatOnACapOrAlongTheSideTouchesAtBothEnds() {
        // lying flat on the top cap, 2 mm deep: both ends carry it, as ODE does for parallel capsules
        assertEquals(2, collide(new double[] {0, HALF + r - 0.002, 0.005, 1, 0, 0}));
        assertContact(0, -L, HALF - 0.001, 0.005, 0, 1, 0, 0.002);
        assertContact(1, L, HALF - 0.001, 0.005, 0, 1, 0, 0.002);
        // along the side, 1 mm deep
        assertEquals(2, collide(new double[] {0, 0, R + r - 0.001, 0, 1, 0}));
        assertContact(0, 0, -L, R - 0.0005, 0, 0, 1, 0.001);
        assertContact(1, 0, L, R - 0.0005, 0, 0, 1, 0.001);
    }

    @Test
    void separatedShapesDoNotTouch() {
        assertEquals(0, collide(new double[] {0, 0, R + r + 1e-6, 1, 0, 0}));
        assertEquals(0, collide(new double[] {0, HALF + r + 1e-6, 0, 0, 0, 1}));
    }

    @Test
    void depthAgreesWithABruteForceSearchAlongTheCapsule() {
        SplittableRandom rng = new SplittableRandom(3);
        int touching = 0;
        for (int trial = 0; trial < 2000; trial++) {
            double[] cap = randomCapsuleNearTheCan(rng);
            int n = collide(cap);
            double deepest = bruteForceDepth(cap);
            if (deepest > r - 1e-5) {
                continue; // the axis enters the can, where the brute force reads no distance
            }
            if (n == 0) {
                // 1e-6 m: the brute force samples s every 4e-5 m, so it can only read a little less deep
                assertTrue(deepest <= 1e-6, "missed a contact " + deepest + " deep, trial " + trial);
                continue;
            }
            touching++;
            double depth = 0;
            for (int i = 0; i < n; i++) {
                depth = Math.max(depth, out[i * C + 6]);
            }
            assertEquals(deepest, depth, 1e-6, "depth, trial " + trial);
        }
        assertTrue(touching > 300, "trials touching: " + touching);
    }

    @Test
    void contactMovesContinuouslyWithThePoses() {
        // nudging the capsule by 1e-9 m moves a contact by about as much: no jumps
        // (libccd's single contact jumped by millimetres between nearby poses)
        SplittableRandom rng = new SplittableRandom(5);
        int checked = 0;
        double[] first = new double[C];
        for (int trial = 0; trial < 2000; trial++) {
            double[] cap = randomCapsuleNearTheCan(rng);
            if (collide(cap) != 1 || out[6] > r - 1e-5) {
                continue; // no single contact, or the axis enters the can (far deeper than contacts get)
            }
            System.arraycopy(out, 0, first, 0, C);
            double[] nudged = cap.clone();
            for (int k = 0; k < 3; k++) {
                nudged[k] += 1e-9 * (rng.nextDouble() - 0.5);
            }
            if (collide(nudged) != 1) {
                continue;
            }
            checked++;
            for (int k = 0; k < C; k++) {
                // 1e-6: a thousand times the nudge, far below a jump across the contact patch
                assertEquals(first[k], out[k], 1e-6, "entry " + k + ", trial " + trial);
            }
        }
        assertTrue(checked > 300, "trials checked: " + checked);
    }

    @Test
    void normalPointsIntoTheFirstGeomAsOdeExpects() {
        DCylinder can = OdeHelper.createCylinder(null, R, 2 * HALF);
        DCapsule finger = OdeHelper.createCapsule(null, r, 2 * L);
        DMatrix3 alongX = new DMatrix3(0, 0, 1, 0, 1, 0, -1, 0, 0); // the geom's z axis along world x
        can.setPosition(0, 0, 0);
        can.setRotation(alongX);
        finger.setPosition(0, 0, R + r - 0.001); // along y: crossing the can's side from above
        finger.setRotation(new DMatrix3(1, 0, 0, 0, 0, 1, 0, -1, 0));
        DContactGeomBuffer buffer = new DContactGeomBuffer(4);
        assertEquals(1, collider.dColliderFn(can, finger, 4, buffer));
        // ODE: the normal points from o2 into o1, here from the finger down into the can
        assertEquals(-1, buffer.get(0).normal.get2(), 1e-12);
        assertEquals(0.001, buffer.get(0).depth, 1e-12);
        assertEquals(1, collider.dColliderFn(finger, can, 4, buffer));
        assertEquals(1, buffer.get(0).normal.get2(), 1e-12);
        assertTrue(buffer.get(0).g1 == finger && buffer.get(0).g2 == can, "geoms in the order given");
    }

    private void assertContact(int i, double x, double y, double z, double nx, double ny, double nz, double depth) {
        double[] expected = {x, y, z, nx, ny, nz, depth};
        for (int k = 0; k < C; k++) {
            assertEquals(expected[k], out[i * C + k], 1e-12, "contact " + i + " entry " + k);
        }
    }

    /** A capsule centred within 6 cm of the can's centre, in a random direction. */
    private static double[] randomCapsuleNearTheCan(SplittableRandom rng) {
        double[] cap = new double[6];
        for (int k = 0; k < 3; k++) {
            cap[k] = 0.12 * (rng.nextDouble() - 0.5);
        }
        double ux = rng.nextGaussian(), uy = rng.nextGaussian(), uz = rng.nextGaussian();
        double n = Math.sqrt(ux * ux + uy * uy + uz * uz);
        cap[3] = ux / n;
        cap[4] = uy / n;
        cap[5] = uz / n;
        return cap;
    }

    /** r minus the least distance from 1001 points of the capsule's axis to the can (0 inside). */
    private static double bruteForceDepth(double[] cap) {
        double least = Double.MAX_VALUE;
        for (int i = 0; i <= 1000; i++) {
            double s = -L + 2 * L * i / 1000.0;
            double x = cap[0] + s * cap[3], y = cap[1] + s * cap[4], z = cap[2] + s * cap[5];
            // the can's nearest point: y clamped to the caps, (x, z) clamped to the disc
            double ny = Math.max(-HALF, Math.min(HALF, y));
            double rho = Math.hypot(x, z), scale = rho > R ? R / rho : 1;
            double d = Math.sqrt(Math.pow(x - x * scale, 2) + Math.pow(y - ny, 2) + Math.pow(z - z * scale, 2));
            least = Math.min(least, d);
        }
        return r - least;
    }
}
