package handsim.sim.island;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * RigidBodies computes its stages in local variables and in two passes over the bodies, for
 * speed; the results must be those of the plain formulation, matrix by matrix and body by body,
 * to the bit (docs/design.md: the step's results unchanged to the bit). The reference here is that
 * formulation written with Matrix3's array operations: R I R^T, L = I w, (I - h [L]x)^-1 by
 * Matrix3.invert, the gyroscopic torque (I (I - h [L]x)^-1 - 1) L / h; then the velocities, the
 * quaternion moved by its derivative and normalised, the rotation matrix, damping.
 */
@Tag("fast")
class RigidBodiesTest {

    private static final double LINEAR_DAMPING = 1e-4, ANGULAR_DAMPING = 2e-4;

    /**
     * The step's h, and a long one (50 ms) under which the quaternion's derivative and the
     * velocity changes are large enough for a regrouped sum to show in the bits.
     */
    @Test
    void prepareAndIntegrateGiveThePlainFormulationsBits() {
        for (double h : new double[] {2e-4, 0.05}) {
            check(h);
        }
    }

    private static void check(double h) {
        for (long seed = 1; seed <= 40; seed++) {
            SplittableRandom rng = new SplittableRandom(seed);
            int n = 5;
            RigidBodies bodies = random(rng, n);
            RigidBodies reference = copy(bodies, n);
            bodies.prepare(h, 0, -9.81, 0);
            prepare(reference, h, 0, -9.81, 0);
            assertSameBits(seed, "prepare: torque", reference.torque, bodies.torque);
            assertSameBits(seed, "prepare: force", reference.force, bodies.force);
            assertSameBits(seed, "prepare: world inverse inertia", reference.inverseInertiaWorld, bodies.inverseInertiaWorld);
            bodies.integrate(h, LINEAR_DAMPING, ANGULAR_DAMPING);
            integrate(reference, h, LINEAR_DAMPING, ANGULAR_DAMPING);
            assertSameBits(seed, "integrate: position", reference.position, bodies.position);
            assertSameBits(seed, "integrate: orientation", reference.orientation, bodies.orientation);
            assertSameBits(seed, "integrate: rotation", reference.rotation, bodies.rotation);
            assertSameBits(seed, "integrate: velocity", reference.velocity, bodies.velocity);
            assertSameBits(seed, "integrate: angular velocity", reference.angularVelocity, bodies.angularVelocity);
        }
    }

    /** n bodies, the last kinematic: random masses, inertias (symmetric, positive definite), poses, velocities, forces. */
    private static RigidBodies random(SplittableRandom rng, int n) {
        RigidBodies b = new RigidBodies(n);
        for (int i = 0; i < n; i++) {
            if (i == n - 1) {
                b.setKinematic(i);
            } else {
                double p = rng.nextDouble(-0.2, 0.2), q = rng.nextDouble(-0.2, 0.2), r = rng.nextDouble(-0.2, 0.2);
                double[] m = {rng.nextDouble(0.5, 2), p, q, p, rng.nextDouble(0.5, 2), r, q, r, rng.nextDouble(0.5, 2)};
                for (int k = 0; k < 9; k++) {
                    m[k] *= 1e-4;
                }
                b.setMass(i, rng.nextDouble(0.01, 1), m);
            }
            double w = rng.nextDouble(-1, 1), x = rng.nextDouble(-1, 1), y = rng.nextDouble(-1, 1), z = rng.nextDouble(-1, 1);
            double l = Math.sqrt(w * w + x * x + y * y + z * z);
            b.orientation[4 * i] = w / l;
            b.orientation[4 * i + 1] = x / l;
            b.orientation[4 * i + 2] = y / l;
            b.orientation[4 * i + 3] = z / l;
            Matrix3.fromQuaternion(b.orientation, 4 * i, b.rotation, 9 * i);
            for (int k = 0; k < 3; k++) {
                b.position[3 * i + k] = rng.nextDouble(-1, 1);
                b.velocity[3 * i + k] = rng.nextDouble(-2, 2);
                b.angularVelocity[3 * i + k] = rng.nextDouble(-30, 30);
                b.force[3 * i + k] = rng.nextDouble(-1, 1);
                b.torque[3 * i + k] = rng.nextDouble(-1e-2, 1e-2);
            }
        }
        return b;
    }

    private static RigidBodies copy(RigidBodies from, int n) {
        RigidBodies to = new RigidBodies(n);
        for (int i = 0; i < n; i++) {
            if (from.inverseMass[i] > 0) {
                to.setMass(i, from.mass[i], java.util.Arrays.copyOfRange(from.inertia, 9 * i, 9 * i + 9));
            } else {
                to.setKinematic(i);
            }
        }
        for (double[][] pair : new double[][][] {{from.position, to.position}, {from.orientation, to.orientation},
            {from.rotation, to.rotation}, {from.velocity, to.velocity}, {from.angularVelocity, to.angularVelocity},
            {from.force, to.force}, {from.torque, to.torque}}) {
            System.arraycopy(pair[0], 0, pair[1], 0, pair[0].length);
        }
        return to;
    }

    /** The first stage, with scratch matrices and Matrix3's operations. */
    private static void prepare(RigidBodies b, double h, double gx, double gy, double gz) {
        double[] s = new double[9], inertia = new double[9], a = new double[9], c = new double[9], v = new double[3];
        for (int i = 0; i < b.count; i++) {
            if (!b.dynamic(i)) {
                continue;
            }
            int f = 3 * i, m = 9 * i;
            b.force[f] += b.mass[i] * gx;
            b.force[f + 1] += b.mass[i] * gy;
            b.force[f + 2] += b.mass[i] * gz;
            rotate(b.rotation, m, b.inverseInertia, m, b.inverseInertiaWorld, m, s);
            rotate(b.rotation, m, b.inertia, m, inertia, 0, s);
            Matrix3.multiply(inertia, 0, b.angularVelocity, f, v, 0);
            double lx = v[0], ly = v[1], lz = v[2];
            System.arraycopy(inertia, 0, c, 0, 9);
            c[1] += h * lz;
            c[2] -= h * ly;
            c[3] -= h * lz;
            c[5] += h * lx;
            c[6] += h * ly;
            c[7] -= h * lx;
            if (Matrix3.invert(c, 0, a, 0) == 0) {
                continue;
            }
            multiply3(inertia, a, c);
            c[0] -= 1;
            c[4] -= 1;
            c[8] -= 1;
            double k = 1 / h;
            v[0] = lx * k;
            v[1] = ly * k;
            v[2] = lz * k;
            b.torque[f] += c[0] * v[0] + c[1] * v[1] + c[2] * v[2];
            b.torque[f + 1] += c[3] * v[0] + c[4] * v[1] + c[5] * v[2];
            b.torque[f + 2] += c[6] * v[0] + c[7] * v[1] + c[8] * v[2];
        }
    }

    /** The last stages, one body at a time. */
    private static void integrate(RigidBodies b, double h, double linearScale, double angularScale) {
        double[] v = new double[3];
        for (int i = 0; i < b.count; i++) {
            int f = 3 * i, q = 4 * i;
            if (!b.dynamic(i)) {
                java.util.Arrays.fill(b.force, f, f + 3, 0);
                java.util.Arrays.fill(b.torque, f, f + 3, 0);
                continue;
            }
            double hm = h * b.inverseMass[i];
            for (int k = 0; k < 3; k++) {
                b.velocity[f + k] += b.force[f + k] * hm;
                b.torque[f + k] *= h;
            }
            Matrix3.multiply(b.inverseInertiaWorld, 9 * i, b.torque, f, v, 0);
            for (int k = 0; k < 3; k++) {
                b.angularVelocity[f + k] += v[k];
                b.position[f + k] += b.velocity[f + k] * h;
            }
            double wx = b.angularVelocity[f], wy = b.angularVelocity[f + 1], wz = b.angularVelocity[f + 2];
            double[] o = b.orientation;
            double q0 = o[q], q1 = o[q + 1], q2 = o[q + 2], q3 = o[q + 3];
            double d0 = 0.5 * (-wx * q1 - wy * q2 - wz * q3);
            double d1 = 0.5 * (wx * q0 + wy * q3 - wz * q2);
            double d2 = 0.5 * (-wx * q3 + wy * q0 + wz * q1);
            double d3 = 0.5 * (wx * q2 - wy * q1 + wz * q0);
            q0 += d0 * h;
            q1 += d1 * h;
            q2 += d2 * h;
            q3 += d3 * h;
            o[q] = q0;
            o[q + 1] = q1;
            o[q + 2] = q2;
            o[q + 3] = q3;
            RigidBodies.normalise(o, q);
            Matrix3.fromQuaternion(o, q, b.rotation, 9 * i);
            RigidBodies.damp(b.velocity, f, linearScale);
            RigidBodies.damp(b.angularVelocity, f, angularScale);
            java.util.Arrays.fill(b.force, f, f + 3, 0);
            java.util.Arrays.fill(b.torque, f, f + 3, 0);
        }
    }

    /** out = r t r^T through the scratch s = t r^T. */
    private static void rotate(double[] r, int ri, double[] t, int ti, double[] out, int oi, double[] s) {
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                s[3 * i + j] = t[ti + 3 * i] * r[ri + 3 * j] + t[ti + 3 * i + 1] * r[ri + 3 * j + 1] + t[ti + 3 * i + 2] * r[ri + 3 * j + 2];
            }
        }
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                out[oi + 3 * i + j] = r[ri + 3 * i] * s[j] + r[ri + 3 * i + 1] * s[3 + j] + r[ri + 3 * i + 2] * s[6 + j];
            }
        }
    }

    /** out = x y (3x3, row-major). */
    private static void multiply3(double[] x, double[] y, double[] out) {
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                out[3 * i + j] = x[3 * i] * y[j] + x[3 * i + 1] * y[3 + j] + x[3 * i + 2] * y[6 + j];
            }
        }
    }

    private static void assertSameBits(long seed, String what, double[] expected, double[] actual) {
        for (int i = 0; i < expected.length; i++) {
            assertEquals(Double.doubleToRawLongBits(expected[i]), Double.doubleToRawLongBits(actual[i]),
                    "seed " + seed + ", " + what + "[" + i + "]: " + actual[i] + " against " + expected[i]);
        }
    }
}
