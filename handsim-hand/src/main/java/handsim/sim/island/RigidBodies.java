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

    private final double[] a = new double[9];
    private final double[] b = new double[9];
    private final double[] c = new double[9];
    private final double[] v = new double[3];

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
        for (int i = 0; i < count; i++) {
            if (!dynamic(i)) {
                continue;
            }
            int f = 3 * i, m = 9 * i;
            force[f] += mass[i] * gx;
            force[f + 1] += mass[i] * gy;
            force[f + 2] += mass[i] * gz;
            Matrix3.rotateTensor(rotation, m, inverseInertia, m, inverseInertiaWorld, m, a);
            // the implicit gyroscopic torque
            Matrix3.rotateTensor(rotation, m, inertia, m, b, 0, a);
            Matrix3.multiply(b, 0, angularVelocity, f, v, 0);
            double lx = v[0], ly = v[1], lz = v[2];
            // c = I - h [L]x
            System.arraycopy(b, 0, c, 0, 9);
            c[1] += h * lz;
            c[2] -= h * ly;
            c[3] -= h * lz;
            c[5] += h * lx;
            c[6] += h * ly;
            c[7] -= h * lx;
            if (Matrix3.invert(c, 0, a, 0) == 0) {
                continue;
            }
            // c = I (I - h [L]x)^-1 - 1, applied to L / h
            Matrix3.multiply3(b, 0, a, 0, c, 0);
            c[0] -= 1;
            c[4] -= 1;
            c[8] -= 1;
            double k = 1 / h;
            v[0] = lx * k;
            v[1] = ly * k;
            v[2] = lz * k;
            torque[f] += c[0] * v[0] + c[1] * v[1] + c[2] * v[2];
            torque[f + 1] += c[3] * v[0] + c[4] * v[1] + c[5] * v[2];
            torque[f + 2] += c[6] * v[0] + c[7] * v[1] + c[8] * v[2];
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
        for (int i = 0; i < count; i++) {
            if (!dynamic(i)) {
                if (active[i]) {
                    clearAccumulators(i);
                }
                continue;
            }
            int f = 3 * i, q = 4 * i;
            double hm = h * inverseMass[i];
            for (int k = 0; k < 3; k++) {
                velocity[f + k] += force[f + k] * hm;
                torque[f + k] *= h;
            }
            Matrix3.multiply(inverseInertiaWorld, 9 * i, torque, f, v, 0);
            for (int k = 0; k < 3; k++) {
                angularVelocity[f + k] += v[k];
                position[f + k] += velocity[f + k] * h;
            }
            double wx = angularVelocity[f], wy = angularVelocity[f + 1], wz = angularVelocity[f + 2];
            double q0 = orientation[q], q1 = orientation[q + 1], q2 = orientation[q + 2], q3 = orientation[q + 3];
            double d0 = 0.5 * (-wx * q1 - wy * q2 - wz * q3);
            double d1 = 0.5 * (wx * q0 + wy * q3 - wz * q2);
            double d2 = 0.5 * (-wx * q3 + wy * q0 + wz * q1);
            double d3 = 0.5 * (wx * q2 - wy * q1 + wz * q0);
            q0 += d0 * h;
            q1 += d1 * h;
            q2 += d2 * h;
            q3 += d3 * h;
            double l = q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3;
            if (l > 0) {
                l = 1 / Math.sqrt(l);
                q0 *= l;
                q1 *= l;
                q2 *= l;
                q3 *= l;
            }
            orientation[q] = q0;
            orientation[q + 1] = q1;
            orientation[q + 2] = q2;
            orientation[q + 3] = q3;
            Matrix3.fromQuaternion(orientation, q, rotation, 9 * i);
            damp(velocity, f, linearScale);
            damp(angularVelocity, f, angularScale);
            clearAccumulators(i);
        }
    }

    private static void damp(double[] vel, int f, double scale) {
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
