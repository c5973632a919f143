package handsim.sim.island;

import java.util.Arrays;

/**
 * The island's rigid bodies as flat arrays, one slot per body (3 numbers per vector, 4 per
 * quaternion (w, x, y, z), 9 per 3x3 matrix, row-major), and the per-body stages of the step:
 * gravity and the world-frame inverse inertia, the implicit gyroscopic torque, the free motion
 * the constraints act against, and the integration of velocities and poses. A body is a
 * position of its centre of mass (m, world), an orientation, velocities (m/s, rad/s, world) and
 * the force and torque accumulated for the next step (N, N m, world), cleared by the step. A
 * kinematic body (inverse mass 0) takes part in joints but never moves; an inactive slot (the
 * object before it is thrown) takes part in nothing.
 */
public final class RigidBodies {

    public final int count;
    /** Centre of mass, m (world). */
    public final double[] position;
    /** Orientation quaternion (w, x, y, z), unit length. */
    public final double[] orientation;
    /** The rotation matrix of the orientation, row-major. */
    public final double[] rotation;
    /** Linear velocity of the centre of mass, m/s. */
    public final double[] velocity;
    /** Angular velocity, rad/s (world). */
    public final double[] angularVelocity;
    /** Force accumulated for the next step, N (world); the step adds gravity and then clears it. */
    public final double[] force;
    /** Torque accumulated for the next step, N m (world); cleared by the step. */
    public final double[] torque;

    final double[] mass;
    final double[] inverseMass;
    /** Inertia about the centre of mass in the body frame, kg m^2, and its inverse. */
    final double[] inertia;
    final double[] inverseInertia;
    /** The inverse inertia in the world frame, computed each step. */
    final double[] inverseInertiaWorld;
    final boolean[] active;

    /** Scratch: a body's world inertia, then the inverse of I - h [L]x. */
    private final double[] b = new double[18];

    public RigidBodies(int count) {
        this.count = count;
        position = new double[3 * count];
        orientation = new double[4 * count];
        rotation = new double[9 * count];
        velocity = new double[3 * count];
        angularVelocity = new double[3 * count];
        force = new double[3 * count];
        torque = new double[3 * count];
        mass = new double[count];
        inverseMass = new double[count];
        inertia = new double[9 * count];
        inverseInertia = new double[9 * count];
        inverseInertiaWorld = new double[9 * count];
        active = new boolean[count];
        for (int i = 0; i < count; i++) {
            orientation[4 * i] = 1;
            rotation[9 * i] = rotation[9 * i + 4] = rotation[9 * i + 8] = 1;
        }
    }

    /**
     * Body {@code i}'s mass (kg) and inertia about its centre of mass in its own frame (kg m^2,
     * symmetric, row-major); the body becomes active and dynamic.
     */
    public void setMass(int i, double m, double[] bodyInertia) {
        if (!(m > 0)) {
            throw new IllegalArgumentException("body " + i + ": mass must be positive, got " + m);
        }
        double det = Matrix3.invert(bodyInertia, 0, inverseInertia, 9 * i);
        if (!(det > 0)) {
            throw new IllegalArgumentException("body " + i + ": the inertia is not positive definite");
        }
        mass[i] = m;
        inverseMass[i] = 1 / m;
        System.arraycopy(bodyInertia, 0, inertia, 9 * i, 9);
        active[i] = true;
    }

    /** Body {@code i} becomes active and kinematic: joints hold against it, nothing moves it. */
    public void setKinematic(int i) {
        mass[i] = 0;
        inverseMass[i] = 0;
        Arrays.fill(inertia, 9 * i, 9 * i + 9, 0);
        Arrays.fill(inverseInertia, 9 * i, 9 * i + 9, 0);
        active[i] = true;
    }

    /** Takes body {@code i} out of the step (an empty object slot). */
    public void deactivate(int i) {
        active[i] = false;
    }

    boolean dynamic(int i) {
        return active[i] && inverseMass[i] > 0;
    }

    /**
     * The first stage for every dynamic body: gravity into the force, the world-frame inverse
     * inertia R I^-1 R^T, and the gyroscopic torque of the implicit scheme (Lacoursière 2006, as
     * ODE applies it): with I = R I_body R^T and L = I w, the torque (I (I - h [L]x)^-1 - 1) L / h,
     * which keeps a spinning body's energy from growing as the explicit w x I w would.
     */
    void prepare(double h, double gx, double gy, double gz) {
        double[] r = rotation;
        for (int i = 0; i < count; i++) {
            if (!dynamic(i)) {
                continue;
            }
            int f = 3 * i, m = 9 * i;
            force[f] += mass[i] * gx;
            force[f + 1] += mass[i] * gy;
            force[f + 2] += mass[i] * gz;
            double r0 = r[m], r1 = r[m + 1], r2 = r[m + 2], r3 = r[m + 3], r4 = r[m + 4], r5 = r[m + 5], r6 = r[m + 6], r7 = r[m + 7],
                    r8 = r[m + 8];
            Matrix3.rotateTensor(r0, r1, r2, r3, r4, r5, r6, r7, r8, inverseInertia, m, inverseInertiaWorld, m);
            // the implicit gyroscopic torque, with I = b
            double[] b = this.b;
            Matrix3.rotateTensor(r0, r1, r2, r3, r4, r5, r6, r7, r8, inertia, m, b, 0);
            double b0 = b[0], b1 = b[1], b2 = b[2], b3 = b[3], b4 = b[4], b5 = b[5], b6 = b[6], b7 = b[7], b8 = b[8];
            double wx = angularVelocity[f], wy = angularVelocity[f + 1], wz = angularVelocity[f + 2];
            double lx = b0 * wx + b1 * wy + b2 * wz;
            double ly = b3 * wx + b4 * wy + b5 * wz;
            double lz = b6 * wx + b7 * wy + b8 * wz;
            // c = I - h [L]x
            double c0 = b0, c1 = b1 + h * lz, c2 = b2 - h * ly;
            double c3 = b3 - h * lz, c4 = b4, c5 = b5 + h * lx;
            double c6 = b6 + h * ly, c7 = b7 - h * lx, c8 = b8;
            // its inverse, a
            if (Matrix3.invert(c0, c1, c2, c3, c4, c5, c6, c7, c8, b, 9) == 0) {
                continue;
            }
            double a0 = b[9], a1 = b[10], a2 = b[11], a3 = b[12], a4 = b[13], a5 = b[14], a6 = b[15], a7 = b[16], a8 = b[17];
            // I (I - h [L]x)^-1 - 1, applied to L / h
            double e0 = b0 * a0 + b1 * a3 + b2 * a6 - 1, e1 = b0 * a1 + b1 * a4 + b2 * a7, e2 = b0 * a2 + b1 * a5 + b2 * a8;
            double e3 = b3 * a0 + b4 * a3 + b5 * a6, e4 = b3 * a1 + b4 * a4 + b5 * a7 - 1, e5 = b3 * a2 + b4 * a5 + b5 * a8;
            double e6 = b6 * a0 + b7 * a3 + b8 * a6, e7 = b6 * a1 + b7 * a4 + b8 * a7, e8 = b6 * a2 + b7 * a5 + b8 * a8 - 1;
            double rh = 1 / h;
            double vx = lx * rh, vy = ly * rh, vz = lz * rh;
            torque[f] += e0 * vx + e1 * vy + e2 * vz;
            torque[f + 1] += e3 * vx + e4 * vy + e5 * vz;
            torque[f + 2] += e6 * vx + e7 * vy + e8 * vz;
        }
    }

    /**
     * Body {@code i}'s free motion as the constraints see it: -(v / h + M^-1 f) in {@code out}
     * at {@code at} (linear 3, angular 3), the velocity change the constraint impulses work
     * against over one step of h seconds.
     */
    void freeMotion(int i, double h, double[] out, int at) {
        double rh = 1 / h;
        double im = inverseMass[i];
        int f = 3 * i;
        for (int k = 0; k < 3; k++) {
            out[at + k] = -(force[f + k] * im + velocity[f + k] * rh);
        }
        Matrix3.multiply(inverseInertiaWorld, 9 * i, torque, f, out, at + 3);
        for (int k = 0; k < 3; k++) {
            out[at + 3 + k] = -(angularVelocity[f + k] * rh) - out[at + 3 + k];
        }
    }

    /** Adds h times the constraint acceleration {@code fc} (6 per body: M^-1 J^T lambda) to body {@code i}'s velocities. */
    void addConstraintVelocity(int i, double h, double[] fc) {
        int f = 3 * i, c6 = 6 * i;
        for (int k = 0; k < 3; k++) {
            velocity[f + k] += h * fc[c6 + k];
            angularVelocity[f + k] += h * fc[c6 + 3 + k];
        }
    }

    /**
     * The last stages for every dynamic body: the velocity change of the applied force and
     * torque, the pose moved by the new velocities over h (the quaternion by its derivative
     * 0.5 (0, w) q, renormalised), air damping as a per-step scale (the velocity times 1 -
     * {@code linearScale}, 1 - {@code angularScale}), and the accumulators cleared.
     */
    void integrate(double h, double linearScale, double angularScale) {
        // two passes over the bodies, each body's arithmetic as one pass would do it: the short
        // second pass lets the CPU overlap the bodies' square roots and divisions
        for (int i = 0; i < count; i++) {
            if (!dynamic(i)) {
                continue;
            }
            int f = 3 * i, q = 4 * i;
            double hm = h * inverseMass[i];
            for (int k = 0; k < 3; k++) {
                velocity[f + k] += force[f + k] * hm;
                position[f + k] += velocity[f + k] * h;
            }
            // the angular velocity change M^-1 (h torque)
            double[] ii = inverseInertiaWorld;
            int m = 9 * i;
            double tx = torque[f] * h, ty = torque[f + 1] * h, tz = torque[f + 2] * h;
            double wx = angularVelocity[f] + (ii[m] * tx + ii[m + 1] * ty + ii[m + 2] * tz);
            double wy = angularVelocity[f + 1] + (ii[m + 3] * tx + ii[m + 4] * ty + ii[m + 5] * tz);
            double wz = angularVelocity[f + 2] + (ii[m + 6] * tx + ii[m + 7] * ty + ii[m + 8] * tz);
            angularVelocity[f] = wx;
            angularVelocity[f + 1] = wy;
            angularVelocity[f + 2] = wz;
            // the quaternion moved by its derivative, normalised in the second pass
            double q0 = orientation[q], q1 = orientation[q + 1], q2 = orientation[q + 2], q3 = orientation[q + 3];
            orientation[q] = q0 + 0.5 * (-wx * q1 - wy * q2 - wz * q3) * h;
            orientation[q + 1] = q1 + 0.5 * (wx * q0 + wy * q3 - wz * q2) * h;
            orientation[q + 2] = q2 + 0.5 * (-wx * q3 + wy * q0 + wz * q1) * h;
            orientation[q + 3] = q3 + 0.5 * (wx * q2 - wy * q1 + wz * q0) * h;
        }
        for (int i = 0; i < count; i++) {
            if (!dynamic(i)) {
                if (active[i]) {
                    clearAccumulators(i);
                }
                continue;
            }
            int f = 3 * i, q = 4 * i;
            normalise(orientation, q);
            Matrix3.fromQuaternion(orientation, q, rotation, 9 * i);
            damp(velocity, f, linearScale);
            damp(angularVelocity, f, angularScale);
            clearAccumulators(i);
        }
    }

    /** The quaternion at {@code q} made unit length, in place (left as it is when zero). */
    static void normalise(double[] o, int q) {
        double q0 = o[q], q1 = o[q + 1], q2 = o[q + 2], q3 = o[q + 3];
        double l = q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3;
        if (l > 0) {
            l = 1 / Math.sqrt(l);
            o[q] = q0 * l;
            o[q + 1] = q1 * l;
            o[q + 2] = q2 * l;
            o[q + 3] = q3 * l;
        }
    }

    /** Air damping of one body's velocity (3 at {@code f}): times 1 - {@code scale} when it is not zero. */
    static void damp(double[] vel, int f, double scale) {
        if (scale != 0 && vel[f] * vel[f] + vel[f + 1] * vel[f + 1] + vel[f + 2] * vel[f + 2] > 0) {
            double k = 1 - scale;
            vel[f] *= k;
            vel[f + 1] *= k;
            vel[f + 2] *= k;
        }
    }

    private void clearAccumulators(int i) {
        int f = 3 * i;
        force[f] = force[f + 1] = force[f + 2] = 0;
        torque[f] = torque[f + 1] = torque[f + 2] = 0;
    }
}
