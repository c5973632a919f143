package handsim.sim.ode;

import handsim.math.Vec3;
import handsim.model.Body;
import handsim.model.Dof;
import handsim.model.HandModel;
import handsim.model.Joint;
import handsim.model.MassProperties;
import handsim.sim.SimConfig;
import handsim.sim.island.Articulation;
import handsim.sim.island.ContactPoints;
import handsim.sim.island.IslandStep;
import handsim.sim.island.RigidBodies;
import org.ode4j.math.DMatrix3;
import org.ode4j.math.DMatrix3C;
import org.ode4j.math.DQuaternionC;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.internal.DxBody;

/**
 * handsim's own step driving ode4j's bodies: each step reads the bodies' poses, velocities and
 * accumulated forces and torques from ode4j, steps them with an {@link IslandStep} (the joints
 * of the model as {@link OdeWorld} built them, the contact geometry ode4j's colliders generated,
 * no contact joints), and writes the result back, the geoms told that their bodies moved. The
 * bodies are the model's (by index), then the fixed torso, then the object's slot.
 */
final class HandsimStepper {

    private final int torso;
    private final int object;
    private final IslandStep step;
    private final RigidBodies b;
    private final DBody[] bodies;

    HandsimStepper(HandModel model, SimConfig config, OdeWorld w) {
        int n = model.bodyCount();
        torso = n;
        object = n + 1;
        bodies = w.bodies;
        b = new RigidBodies(n + 2);
        for (Body body : model.bodies()) {
            b.setMass(body.index(), body.mass().mass(), inertia(body.mass()));
        }
        b.setKinematic(torso);
        Articulation a = articulation(model);
        // ode4j lists bodies newest first: the object, the model's bodies from the last, the torso
        int[] listOrder = new int[n + 2];
        listOrder[0] = object;
        for (int i = 0; i < n; i++) {
            listOrder[1 + i] = n - 1 - i;
        }
        listOrder[n + 1] = torso;
        double h = config.timeStep();
        Vec3 g = config.gravity();
        // the joints' ERP and CFM are the world's, as ode4j's joints take them
        step = new IslandStep(new IslandStep.Settings(h, new double[] {g.x(), g.y(), g.z()}, config.solverIterations(),
                config.sor(), w.world.getERP(), w.world.getCFM(), w.world.getLinearDamping(), w.world.getAngularDamping()),
                b, a, listOrder);
    }

    /**
     * The model's joints in the order {@link OdeWorld} creates them, each ball joint followed by
     * the limits of its Euler angles; anchors relative to each body's centre of mass in the zero
     * configuration (every body then unrotated), axes negated as the engine's.
     */
    private Articulation articulation(HandModel model) {
        Articulation a = new Articulation();
        for (Joint j : model.joints()) {
            int parent = j.isRoot() ? torso : j.parent();
            int child = j.child();
            double[] anchor1 = minus(j.anchor(), j.isRoot() ? Vec3.ZERO : centre(model.bodies().get(parent)));
            double[] anchor2 = minus(j.anchor(), centre(model.bodies().get(child)));
            Dof d0 = model.dofs().get(j.firstDof());
            switch (j.type()) {
                case HINGE -> {
                    double[] axis = engineAxis(d0);
                    a.addHinge(parent, child, anchor1, anchor2, axis, axis, j.firstDof(), d0.lower(), d0.upper());
                }
                case UNIVERSAL -> {
                    Dof d1 = model.dofs().get(j.firstDof() + 1);
                    a.addUniversal(parent, child, anchor1, anchor2, engineAxis(d0), engineAxis(d1), j.firstDof(),
                            d0.lower(), d0.upper(), d1.lower(), d1.upper());
                }
                case BALL -> {
                    a.addBall(parent, child, anchor1, anchor2);
                    double[] lo = new double[3], hi = new double[3];
                    for (int s = 0; s < 3; s++) {
                        Dof d = model.dofs().get(j.firstDof() + s);
                        lo[s] = d.lower();
                        hi[s] = d.upper();
                    }
                    a.addEulerLimits(parent, child, j.firstDof(), lo, hi);
                }
            }
        }
        return a;
    }

    /** A body's centre of mass in the zero configuration, where ode4j placed it. */
    private static Vec3 centre(Body body) {
        return body.origin().plus(body.mass().com());
    }

    private static double[] minus(Vec3 a, Vec3 b) {
        return new double[] {a.x() - b.x(), a.y() - b.y(), a.z() - b.z()};
    }

    /** The DOF's axis negated (see OdeWorld.createJoint), unit length. */
    private static double[] engineAxis(Dof d) {
        Vec3 u = d.axis().times(-1).normalized();
        return new double[] {u.x(), u.y(), u.z()};
    }

    private static double[] inertia(MassProperties m) {
        var i = m.inertia();
        return new double[] {i.xx(), i.xy(), i.xz(), i.xy(), i.yy(), i.yz(), i.xz(), i.yz(), i.zz()};
    }

    /** The object's mass properties; its slot takes part in the step from now on. */
    void objectMass(MassProperties m) {
        b.setMass(object, m.mass(), inertia(m));
    }

    void removeObject() {
        b.deactivate(object);
    }

    int objectIndex() {
        return object;
    }

    ContactPoints contacts() {
        return step.contacts();
    }

    void setSeed(long seed) {
        step.setSeed(seed);
    }

    long seed() {
        return step.seed();
    }

    /** The rows the next step would assemble from the bodies' current state and the contacts collected so far. */
    java.util.List<IslandStep.AssembledRow> assembledRows(DBody objectBody, double[] angles, double[] dofAxes) {
        for (int i = 0; i < bodies.length; i++) {
            read(bodies[i], i);
        }
        if (objectBody != null) {
            read(objectBody, object);
        }
        return step.assembledRows(angles, dofAxes);
    }

    /**
     * One step of every body; {@code angles} and {@code dofAxes} are the joint angles and the
     * DOFs' world axes at the start of the step (the stops').
     */
    void step(DBody objectBody, double[] angles, double[] dofAxes) {
        for (int i = 0; i < bodies.length; i++) {
            read(bodies[i], i);
        }
        if (objectBody != null) {
            read(objectBody, object);
        }
        step.step(angles, dofAxes);
        for (int i = 0; i < bodies.length; i++) {
            write(bodies[i], i);
        }
        if (objectBody != null) {
            write(objectBody, object);
        }
    }

    private void read(DBody body, int i) {
        DVector3C p = body.getPosition();
        DQuaternionC q = body.getQuaternion();
        DMatrix3C r = body.getRotation();
        DVector3C v = body.getLinearVel();
        DVector3C w = body.getAngularVel();
        DVector3C f = body.getForce();
        DVector3C t = body.getTorque();
        int i3 = 3 * i, i4 = 4 * i, i9 = 9 * i;
        b.position[i3] = p.get0();
        b.position[i3 + 1] = p.get1();
        b.position[i3 + 2] = p.get2();
        b.orientation[i4] = q.get0();
        b.orientation[i4 + 1] = q.get1();
        b.orientation[i4 + 2] = q.get2();
        b.orientation[i4 + 3] = q.get3();
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 3; col++) {
                b.rotation[i9 + 3 * row + col] = r.get(row, col);
            }
        }
        b.velocity[i3] = v.get0();
        b.velocity[i3 + 1] = v.get1();
        b.velocity[i3 + 2] = v.get2();
        b.angularVelocity[i3] = w.get0();
        b.angularVelocity[i3 + 1] = w.get1();
        b.angularVelocity[i3 + 2] = w.get2();
        b.force[i3] = f.get0();
        b.force[i3 + 1] = f.get1();
        b.force[i3 + 2] = f.get2();
        b.torque[i3] = t.get0();
        b.torque[i3 + 1] = t.get1();
        b.torque[i3 + 2] = t.get2();
    }

    /** Writes body {@code i} back: pose (the geoms told), velocities, cleared accumulators. */
    private void write(DBody body, int i) {
        int i3 = 3 * i, i4 = 4 * i, i9 = 9 * i;
        DxBody e = (DxBody) body;
        e._q.set(b.orientation[i4], b.orientation[i4 + 1], b.orientation[i4 + 2], b.orientation[i4 + 3]);
        DMatrix3 r = e._posr.Rw();
        double[] m = b.rotation;
        r.set(m[i9], m[i9 + 1], m[i9 + 2], m[i9 + 3], m[i9 + 4], m[i9 + 5], m[i9 + 6], m[i9 + 7], m[i9 + 8]);
        e.dBodySetPosition(b.position[i3], b.position[i3 + 1], b.position[i3 + 2]);
        body.setLinearVel(b.velocity[i3], b.velocity[i3 + 1], b.velocity[i3 + 2]);
        body.setAngularVel(b.angularVelocity[i3], b.angularVelocity[i3 + 1], b.angularVelocity[i3 + 2]);
        body.setForce(0, 0, 0);
        body.setTorque(0, 0, 0);
    }
}
