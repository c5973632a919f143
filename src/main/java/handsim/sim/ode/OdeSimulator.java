package handsim.sim.ode;

import handsim.kin.Frame;
import handsim.kin.Kinematics;
import handsim.kin.Rotations;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.Body;
import handsim.model.Dof;
import handsim.model.HandModel;
import handsim.model.Joint;
import handsim.model.Shape;
import handsim.sim.ContactReport;
import handsim.sim.ObjectSpec;
import handsim.sim.RigidState;
import handsim.sim.SimConfig;
import handsim.sim.SimulationDiverged;
import handsim.sim.StepAccounting;
import handsim.sim.Simulator;
import handsim.sim.WorldSnapshot;
import handsim.sim.WorldState;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.ode4j.math.DMatrix3;
import org.ode4j.math.DQuaternion;
import org.ode4j.math.DQuaternionC;
import org.ode4j.math.DVector3;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DAMotorJoint;
import org.ode4j.ode.DBallJoint;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DBox;
import org.ode4j.ode.DCapsule;
import org.ode4j.ode.DContact;
import org.ode4j.ode.DContactBuffer;
import org.ode4j.ode.DCylinder;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DHingeJoint;
import org.ode4j.ode.DJoint;
import org.ode4j.ode.DJointGroup;
import org.ode4j.ode.DMass;
import org.ode4j.ode.DMisc;
import org.ode4j.ode.DPlane;
import org.ode4j.ode.DSpace;
import org.ode4j.ode.DUniversalJoint;
import org.ode4j.ode.DWorld;
import org.ode4j.ode.OdeConfig;
import org.ode4j.ode.OdeConstants;
import org.ode4j.ode.OdeHelper;
import org.ode4j.ode.internal.DxBody;
import org.ode4j.ode.internal.Rotation;

/**
 * The arm+hand and a thrown object in an ode4j world, stepped with quickStep at the configured
 * h. Contacts are generated only between the object and the hand/arm, the ground and static
 * boxes (the hand does not collide with itself); each contact gets the ERP and CFM of the
 * paper's compliant contact model from the masses of its two bodies.
 */
public final class OdeSimulator implements Simulator {

    static {
        // ODE's analytic colliders for cylinders (cylinder-box clips faces and edges), not
        // libccd's single jumping contact; cylinder-capsule, which ODE has no analytic collider
        // for, is CylinderCapsuleCollider's. Must precede the first use of ode4j's geoms.
        OdeConfig.setLibCCDEndabled(false);
        OdeHelper.initODE2(0);
    }

    /** Per-thread allocation counter, for {@link #setAccounting}. */
    private static final com.sun.management.ThreadMXBean THREADS =
            (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();

    /**
     * Bounding spheres are grown by this much (m) so that rounding can never hide a touching
     * pair: the margin only decides which pairs the exact colliders test.
     */
    private static final double BOUND_MARGIN = 1e-3;

    /** Speed beyond which the state is considered to have exploded, m/s. */
    private static final double DIVERGED_SPEED = 200;

    /**
     * Angular speed beyond which the arm is considered to have exploded, rad/s, checked on the
     * bodies of at least {@link #SPIN_CHECKED_MASS}: the upper arm, the forearm and the palm. In
     * seeded catch loops of every task they turn at most 146 rad/s (the palm, as a club drops;
     * upper arm and forearm under 50), and an unpowered arm falling onto its joint limits whips
     * its palm to about 1,300 rad/s (upper arm and forearm about 300). An arm driven into its
     * shoulder's Euler singularity spun its upper arm past 2,000 rad/s with nothing touching it,
     * 70 ms before it flung the can away at 78 m/s (docs/experiments.md, "Catch"). Finger
     * phalanges (3-30 g) are left out: unpowered, they flop against their limits at over
     * 1,000 rad/s.
     */
    static final double DIVERGED_SPIN = 2000;

    /** Bodies at least this heavy (kg) are checked against {@link #DIVERGED_SPIN}. */
    static final double SPIN_CHECKED_MASS = 0.1;

    private enum Kind { HAND, OBJECT, GROUND, BOX }

    /** What a geometry belongs to; stored as the geom's user data. */
    private record GeomTag(Kind kind, int body) {
    }

    private final HandModel model;
    private final SimConfig config;
    private final Kinematics kin;
    private final DWorld world;
    /** The hand/arm geoms in model order (body, then shape), in no space: {@link #collide} pairs them itself. */
    private final DGeom[] handGeoms;
    /** Per hand geom: its body, and its bounding sphere (centre relative to the body's centre of mass, body frame; radius). */
    private final int[] handGeomBody;
    private final double[] handGeomCentre;
    private final double[] handGeomRadius;
    /** Per object geom: bounding sphere centre (object frame) and radius. */
    private final List<double[]> objectBounds = new ArrayList<>();
    /** Scratch for the world centres of bounding spheres. */
    private final double[] centre = new double[6];
    private final DJointGroup contactGroup;
    private final DPlane ground;
    private final DBody torso;
    private final DBody[] bodies;
    /** Indices of the bodies checked against {@link #DIVERGED_SPIN}. */
    private final int[] spinChecked;
    private final Vec3[] centreOfMass;
    private final DAMotorJoint[] limitMotors;
    private final double[] q;
    private final double[] qd;
    private final double[] tau;
    /** The model's joints (an array: the per-step loops allocate no iterator). */
    private final Joint[] joints;
    /** Per joint: parent body index, or -1 for the fixed torso. */
    private final int[] parentOf;
    /** World rotation (w, x, y, z) of every body after the last step, then the torso's (identity) at index n. */
    private final double[] rotations;
    /** World angular velocity of every body after the last step, then the torso's (zero). */
    private final double[] angularVels;
    /** World axis of every DOF after the last step (3 per DOF): torques and limit motors act about these. */
    private final double[] worldAxes;
    /** Scratch: a joint's relative rotation, and the relative angular velocity in the parent frame. */
    private final double[] relative = new double[4];
    private final double[] omegaWorld = new double[3];
    private final double[] omegaParent = new double[3];
    private final double[] work = new double[Kinematics.WORK];
    private final DVector3 motorAxis = new DVector3();
    private final ContactReport contacts = new ContactReport();
    private final DContactBuffer contactBuffer;
    private final CylinderCapsuleCollider cylinderCapsule = new CylinderCapsuleCollider();
    private final double[] handErp;
    private final double[] handCfm;
    private final List<DGeom> objectGeoms = new ArrayList<>();
    private final List<DGeom> boxes = new ArrayList<>();
    private final List<WorldSnapshot.StaticBox> boxSpecs = new ArrayList<>();
    /** Test bounding spheres before the exact colliders (off only in tests, to check it loses no contact). */
    private boolean broadPhase = true;
    /** The object's rotation (w, x, y, z) while colliding. */
    private final double[] objectRotation = new double[4];
    private DBody object;
    private ObjectSpec objectSpec;
    private double staticErp;
    private double staticCfm;
    private double time;
    private long steps;
    private boolean touchesGround;
    private boolean touchesBox;
    /** Non-null while accounting is on. */
    private StepAccounting accounting;
    private final StepAccounting accounts = new StepAccounting();

    public OdeSimulator(HandModel model, SimConfig config) {
        this.model = model;
        this.config = config;
        this.kin = new Kinematics(model);
        int n = model.bodyCount();
        world = OdeHelper.createWorld();
        Vec3 g = config.gravity();
        world.setGravity(g.x(), g.y(), g.z());
        world.setQuickStepNumIterations(config.solverIterations());
        world.setQuickStepW(config.sor());
        // the paper's damping read as per-second rates: per-step scale = rate * h (SPEC)
        world.setLinearDamping(config.linearDampingPerSecond() * config.timeStep());
        world.setAngularDamping(config.angularDampingPerSecond() * config.timeStep());
        world.setLinearDampingThreshold(0);
        world.setAngularDampingThreshold(0);
        world.setAutoDisableFlag(false);
        contactGroup = OdeHelper.createJointGroup();
        ground = OdeHelper.createPlane(null, 0, 1, 0, config.groundHeight());
        ground.setData(new GeomTag(Kind.GROUND, -1));
        contactBuffer = new DContactBuffer(config.maxContactsPerPair());
        handErp = new double[n];
        handCfm = new double[n];

        // the fixed shoulder: a kinematic body that never moves
        torso = OdeHelper.createBody(world);
        torso.setKinematic();
        bodies = new DBody[n];
        spinChecked = model.bodies().stream().filter(b -> b.mass().mass() >= SPIN_CHECKED_MASS).mapToInt(Body::index).toArray();
        centreOfMass = new Vec3[n];
        List<DGeom> geoms = new ArrayList<>();
        List<double[]> bounds = new ArrayList<>();
        for (Body b : model.bodies()) {
            bodies[b.index()] = createBody(b, geoms, bounds);
        }
        handGeoms = geoms.toArray(new DGeom[0]);
        handGeomBody = new int[handGeoms.length];
        handGeomCentre = new double[3 * handGeoms.length];
        handGeomRadius = new double[handGeoms.length];
        for (int i = 0; i < handGeoms.length; i++) {
            handGeomBody[i] = ((GeomTag) handGeoms[i].getData()).body();
            System.arraycopy(bounds.get(i), 0, handGeomCentre, 3 * i, 3);
            handGeomRadius[i] = bounds.get(i)[3];
        }
        limitMotors = new DAMotorJoint[model.joints().size()];
        for (Joint j : model.joints()) {
            createJoint(j);
        }
        q = new double[model.dofCount()];
        qd = new double[model.dofCount()];
        tau = new double[model.dofCount()];
        joints = model.joints().toArray(new Joint[0]);
        parentOf = new int[model.joints().size()];
        for (Joint j : model.joints()) {
            parentOf[j.index()] = j.isRoot() ? -1 : j.parent();
        }
        rotations = new double[4 * (n + 1)];
        angularVels = new double[3 * (n + 1)];
        rotations[4 * n] = 1;
        worldAxes = new double[3 * model.dofCount()];
        reset(q, 0);
    }

    // ---- construction ---------------------------------------------------------------------

    /**
     * Creates a body at its zero-configuration place: frame at the joint anchor, world-aligned;
     * its geoms and their bounding spheres are appended to {@code geoms} and {@code bounds}.
     */
    private DBody createBody(Body b, List<DGeom> geoms, List<double[]> bounds) {
        DBody body = OdeHelper.createBody(world);
        Vec3 com = b.mass().com();
        centreOfMass[b.index()] = com;
        DMass mass = OdeHelper.createMass();
        mass.setMass(b.mass().mass());
        var i = b.mass().inertia();
        mass.setI(new DMatrix3(i.xx(), i.xy(), i.xz(), i.xy(), i.yy(), i.yz(), i.xz(), i.yz(), i.zz()));
        mass.setC(new DVector3(0, 0, 0));
        body.setMass(mass);
        Vec3 p = b.origin().plus(com);
        body.setPosition(p.x(), p.y(), p.z());
        body.setData(b.index());
        if (b.collides()) {
            for (Shape s : b.shapes()) {
                DGeom geom = createGeom(null, s);
                geom.setBody(body);
                applyOffset(geom, s, com);
                geom.setData(new GeomTag(Kind.HAND, b.index()));
                geoms.add(geom);
                bounds.add(boundingSphere(s, com));
            }
        }
        return body;
    }

    /** An ODE geometry for a shape; capsules and cylinders are along the geom's z axis. */
    private static DGeom createGeom(DSpace space, Shape s) {
        if (s instanceof Shape.Capsule c) {
            return OdeHelper.createCapsule(space, c.radius(), c.length());
        }
        if (s instanceof Shape.Cylinder c) {
            return OdeHelper.createCylinder(space, c.radius(), c.length());
        }
        if (s instanceof Shape.Box b) {
            return OdeHelper.createBox(space, b.size().x(), b.size().y(), b.size().z());
        }
        Shape.Sphere sp = (Shape.Sphere) s;
        return OdeHelper.createSphere(space, sp.radius());
    }

    /**
     * A sphere holding the shape: centre (relative to the body's centre of mass {@code com}) and
     * radius, grown by {@link #BOUND_MARGIN}.
     */
    private static double[] boundingSphere(Shape s, Vec3 com) {
        double r;
        if (s instanceof Shape.Capsule c) {
            r = 0.5 * c.length() + c.radius();
        } else if (s instanceof Shape.Cylinder c) {
            r = Math.hypot(0.5 * c.length(), c.radius());
        } else if (s instanceof Shape.Box b) {
            r = 0.5 * b.size().norm();
        } else {
            r = ((Shape.Sphere) s).radius();
        }
        Vec3 c = s.centroid().minus(com);
        return new double[] {c.x(), c.y(), c.z(), r + BOUND_MARGIN};
    }

    /** Places a body-attached geom relative to the ODE body, whose origin is the centre of mass. */
    private static void applyOffset(DGeom geom, Shape s, Vec3 com) {
        Vec3 centre;
        Quat rot = Quat.IDENTITY;
        if (s instanceof Shape.Capsule c) {
            centre = c.centroid();
            rot = Quat.between(Vec3.Z, c.b().minus(c.a()).normalized());
        } else if (s instanceof Shape.Cylinder c) {
            centre = c.centroid();
            rot = Quat.between(Vec3.Z, c.b().minus(c.a()).normalized());
        } else if (s instanceof Shape.Box b) {
            centre = b.center();
            rot = b.rotation();
        } else {
            centre = ((Shape.Sphere) s).center();
        }
        Vec3 off = centre.minus(com);
        geom.setOffsetPosition(off.x(), off.y(), off.z());
        geom.setOffsetQuaternion(new DQuaternion(rot.w(), rot.x(), rot.y(), rot.z()));
    }

    private DBody parentBody(Joint j) {
        return j.isRoot() ? torso : bodies[j.parent()];
    }

    /**
     * Creates the engine joint while every body is in the zero configuration. ODE measures a
     * joint angle as the parent's rotation relative to the child about the axis, the opposite of
     * {@link Kinematics}; giving ODE the negated axes makes its angles, and so its stops, ours.
     */
    private void createJoint(Joint j) {
        DBody parent = parentBody(j);
        DBody child = bodies[j.child()];
        Vec3 a = j.anchor();
        Dof d0 = model.dofs().get(j.firstDof());
        switch (j.type()) {
            case HINGE -> {
                DHingeJoint h = OdeHelper.createHingeJoint(world);
                h.attach(parent, child);
                h.setAnchor(a.x(), a.y(), a.z());
                h.setAxis(-d0.axis().x(), -d0.axis().y(), -d0.axis().z());
                h.setParamHiStop(d0.upper());
                h.setParamLoStop(d0.lower());
            }
            case UNIVERSAL -> {
                Dof d1 = model.dofs().get(j.firstDof() + 1);
                DUniversalJoint u = OdeHelper.createUniversalJoint(world);
                u.attach(parent, child);
                u.setAnchor(a.x(), a.y(), a.z());
                u.setAxis1(-d0.axis().x(), -d0.axis().y(), -d0.axis().z());
                u.setAxis2(-d1.axis().x(), -d1.axis().y(), -d1.axis().z());
                u.setParam(DJoint.PARAM_N.dParamHiStop1, d0.upper());
                u.setParam(DJoint.PARAM_N.dParamLoStop1, d0.lower());
                u.setParam(DJoint.PARAM_N.dParamHiStop2, d1.upper());
                u.setParam(DJoint.PARAM_N.dParamLoStop2, d1.lower());
            }
            case BALL -> {
                DBallJoint ball = OdeHelper.createBallJoint(world);
                ball.attach(parent, child);
                ball.setAnchor(a.x(), a.y(), a.z());
                // limits on the three Euler angles: a user-mode motor whose axes and angles we
                // set every step from our own decomposition
                DAMotorJoint m = OdeHelper.createAMotorJoint(world);
                m.attach(parent, child);
                m.setMode(DAMotorJoint.AMotorMode.dAMotorUser);
                m.setNumAxes(3);
                for (int s = 0; s < 3; s++) {
                    Dof d = model.dofs().get(j.firstDof() + s);
                    m.setAxis(s, 0, -d.axis().x(), -d.axis().y(), -d.axis().z());
                    m.setParam(hiStop(s), d.upper());
                    m.setParam(loStop(s), d.lower());
                }
                limitMotors[j.index()] = m;
            }
        }
    }

    private static DJoint.PARAM_N loStop(int axis) {
        return switch (axis) {
            case 0 -> DJoint.PARAM_N.dParamLoStop1;
            case 1 -> DJoint.PARAM_N.dParamLoStop2;
            default -> DJoint.PARAM_N.dParamLoStop3;
        };
    }

    private static DJoint.PARAM_N hiStop(int axis) {
        return switch (axis) {
            case 0 -> DJoint.PARAM_N.dParamHiStop1;
            case 1 -> DJoint.PARAM_N.dParamHiStop2;
            default -> DJoint.PARAM_N.dParamHiStop3;
        };
    }

    // ---- Simulator --------------------------------------------------------------------------

    @Override
    public HandModel model() {
        return model;
    }

    @Override
    public SimConfig config() {
        return config;
    }

    @Override
    public double time() {
        return time;
    }

    @Override
    public long stepCount() {
        return steps;
    }

    @Override
    public void reset(double[] angles, long seed) {
        if (angles.length != model.dofCount()) {
            throw new IllegalArgumentException("expected " + model.dofCount() + " joint angles, got " + angles.length);
        }
        clearWorld(seed);
        Frame[] frames = kin.forward(angles);
        for (Body b : model.bodies()) {
            Frame f = frames[b.index()];
            Vec3 centre = f.pointToWorld(centreOfMass[b.index()]);
            setBody(bodies[b.index()], new RigidState(centre, f.rotation(), Vec3.ZERO, Vec3.ZERO));
        }
        java.util.Arrays.fill(tau, 0);
        time = 0;
        steps = 0;
        contacts.clear(0);
        updateJointState();
    }

    /**
     * What {@link #reset} and {@link #restoreState} start from: ODE's generator reseeded (quickStep
     * shuffles constraints with this process-wide generator), the object and the boxes removed,
     * no force or torque accumulated on the arm.
     */
    private void clearWorld(long seed) {
        DMisc.dRandSetSeed(seed);
        removeObject();
        for (DGeom b : boxes) {
            b.destroy();
        }
        boxes.clear();
        boxSpecs.clear();
        contactGroup.empty();
        for (DBody body : bodies) {
            body.setForce(0, 0, 0);
            body.setTorque(0, 0, 0);
        }
        touchesGround = false;
        touchesBox = false;
    }

    @Override
    public WorldState captureState() {
        double[] state = new double[WorldState.PER_BODY * bodies.length];
        for (int b = 0; b < bodies.length; b++) {
            writeBody(bodies[b], state, WorldState.PER_BODY * b);
        }
        Optional<RigidState> o = object == null ? Optional.empty() : Optional.of(objectState());
        return new WorldState(time, steps, state, tau, Optional.ofNullable(objectSpec), o, boxSpecs, DMisc.dRandGetSeed());
    }

    @Override
    public void restoreState(WorldState s) {
        double[] state = s.bodies();
        if (state.length != WorldState.PER_BODY * bodies.length || s.torques().length != tau.length) {
            throw new IllegalArgumentException("the state is of a model with " + state.length / WorldState.PER_BODY
                    + " bodies and " + s.torques().length + " DOFs, this world's has " + bodies.length + " and " + tau.length);
        }
        clearWorld(s.randomSeed());
        for (int b = 0; b < bodies.length; b++) {
            int i = WorldState.PER_BODY * b;
            restoreBody(bodies[b], new RigidState(new Vec3(state[i], state[i + 1], state[i + 2]),
                    new Quat(state[i + 3], state[i + 4], state[i + 5], state[i + 6]),
                    new Vec3(state[i + 7], state[i + 8], state[i + 9]), new Vec3(state[i + 10], state[i + 11], state[i + 12])));
        }
        for (WorldSnapshot.StaticBox box : s.boxes()) {
            addStaticBox(box.center(), box.size());
        }
        if (s.objectSpec().isPresent()) {
            spawnObject(s.objectSpec().get(), s.object().get());
            restoreBody(object, s.object().get());
        }
        System.arraycopy(s.torques(), 0, tau, 0, tau.length);
        time = s.time();
        steps = s.steps();
        contacts.clear(time);
        updateJointState();
    }

    private static void writeBody(DBody b, double[] out, int at) {
        DVector3C p = b.getPosition();
        DQuaternionC r = b.getQuaternion();
        DVector3C v = b.getLinearVel();
        DVector3C w = b.getAngularVel();
        double[] values = {p.get0(), p.get1(), p.get2(), r.get0(), r.get1(), r.get2(), r.get3(),
            v.get0(), v.get1(), v.get2(), w.get0(), w.get1(), w.get2()};
        System.arraycopy(values, 0, out, at, values.length);
    }

    private static void setBody(DBody body, RigidState s) {
        Vec3 p = s.position();
        Quat r = s.orientation();
        body.setPosition(p.x(), p.y(), p.z());
        body.setQuaternion(new DQuaternion(r.w(), r.x(), r.y(), r.z()));
        body.setLinearVel(s.velocity().x(), s.velocity().y(), s.velocity().z());
        body.setAngularVel(s.angularVelocity().x(), s.angularVelocity().y(), s.angularVelocity().z());
    }

    /**
     * {@link #setBody} to a state captured from a stepped world, bit for bit. ODE's setQuaternion
     * normalises the quaternion again, which moves a stepped (already normalised) one by an ulp;
     * so the engine's own quaternion is then set to the captured one and the rotation matrix
     * derived from it as a step derives it.
     */
    private static void restoreBody(DBody body, RigidState s) {
        setBody(body, s); // also tells the body's geoms that it moved
        DxBody engineBody = (DxBody) body;
        Quat r = s.orientation();
        engineBody._q.set(r.w(), r.x(), r.y(), r.z());
        Rotation.dRfromQ(engineBody._posr.Rw(), engineBody._q);
    }

    @Override
    public void readJoints(double[] angles, double[] rates) {
        System.arraycopy(q, 0, angles, 0, q.length);
        System.arraycopy(qd, 0, rates, 0, qd.length);
    }

    @Override
    public void setJointTorques(double[] torques) {
        System.arraycopy(torques, 0, tau, 0, tau.length);
    }

    @Override
    public void step() {
        StepAccounting a = accounting;
        long t0 = a != null ? System.nanoTime() : 0;
        contacts.clear(time);
        touchesGround = false;
        touchesBox = false;
        applyJointTorques();
        // the engine's own allocation: its AMotor setters (until the JIT removes it), the
        // contact joints, and quickStep's per-step arrays
        long bytes0 = a != null ? THREADS.getCurrentThreadAllocatedBytes() : 0;
        updateLimitMotors();
        long t1 = a != null ? System.nanoTime() : 0;
        collide();
        long t2 = a != null ? System.nanoTime() : 0;
        world.quickStep(config.timeStep());
        contactGroup.empty();
        long t3 = 0, bytes = 0;
        if (a != null) {
            t3 = System.nanoTime();
            bytes = THREADS.getCurrentThreadAllocatedBytes() - bytes0;
        }
        time += config.timeStep();
        steps++;
        updateJointState();
        checkDiverged();
        if (a != null) {
            a.add(System.nanoTime() - t0, t2 - t1, t3 - t2, bytes);
        }
    }

    /** eq. (3): each DOF's torque about its current world axis, equal and opposite on the two bodies. */
    private void applyJointTorques() {
        for (Joint j : joints) {
            double tx = 0, ty = 0, tz = 0;
            for (int s = 0; s < j.dofCount(); s++) {
                int d = j.firstDof() + s;
                double t = tau[d];
                tx += t * worldAxes[3 * d];
                ty += t * worldAxes[3 * d + 1];
                tz += t * worldAxes[3 * d + 2];
            }
            bodies[j.child()].addTorque(tx, ty, tz);
            if (!j.isRoot()) {
                bodies[j.parent()].addTorque(-tx, -ty, -tz);
            }
        }
    }

    /** Feeds the ball joints' limit motors the current Euler axes (negated, see createJoint) and angles. */
    private void updateLimitMotors() {
        for (Joint j : joints) {
            DAMotorJoint m = limitMotors[j.index()];
            if (m == null) {
                continue;
            }
            for (int s = 0; s < 3; s++) {
                int d = j.firstDof() + s;
                // ode4j copies the axis; its (x, y, z) overload would allocate a vector each call
                motorAxis.set(-worldAxes[3 * d], -worldAxes[3 * d + 1], -worldAxes[3 * d + 2]);
                m.setAxis(s, 0, motorAxis);
                m.setAngle(s, q[d]);
            }
        }
    }

    /**
     * Joint angles and rates from the bodies' orientations and angular velocities, and the DOFs'
     * world axes for the next step's torques and limit motors.
     */
    private void updateJointState() {
        int n = bodies.length;
        for (int b = 0; b < n; b++) {
            DQuaternionC r = bodies[b].getQuaternion();
            rotations[4 * b] = r.get0();
            rotations[4 * b + 1] = r.get1();
            rotations[4 * b + 2] = r.get2();
            rotations[4 * b + 3] = r.get3();
            DVector3C w = bodies[b].getAngularVel();
            angularVels[3 * b] = w.get0();
            angularVels[3 * b + 1] = w.get1();
            angularVels[3 * b + 2] = w.get2();
        }
        for (Joint j : joints) {
            int p = parentOf[j.index()] < 0 ? n : parentOf[j.index()];
            int c = j.child();
            Rotations.conjMul(rotations, 4 * p, rotations, 4 * c, relative, 0);
            kin.decompose(j, relative[0], relative[1], relative[2], relative[3], q);
            for (int i = 0; i < 3; i++) {
                omegaWorld[i] = angularVels[3 * c + i] - angularVels[3 * p + i];
            }
            Rotations.inverseRotate(rotations, 4 * p, omegaWorld, 0, omegaParent, 0);
            kin.rates(j, q, omegaParent[0], omegaParent[1], omegaParent[2], qd, work);
            kin.worldAxes(j, rotations, 4 * p, q, worldAxes, 3 * j.firstDof());
        }
    }

    private void checkDiverged() {
        for (int i = 0; i < q.length; i++) {
            if (!Double.isFinite(q[i]) || !Double.isFinite(qd[i])) {
                throw new SimulationDiverged("joint " + model.dofs().get(i).name() + " is not finite at t = " + time + " s");
            }
        }
        for (int b : spinChecked) {
            double wx = angularVels[3 * b], wy = angularVels[3 * b + 1], wz = angularVels[3 * b + 2];
            double spin2 = wx * wx + wy * wy + wz * wz;
            if (spin2 > DIVERGED_SPIN * DIVERGED_SPIN) {
                throw new SimulationDiverged("body " + model.bodies().get(b).name() + " spins at " + Math.sqrt(spin2)
                        + " rad/s at t = " + time + " s");
            }
        }
        if (object != null) {
            DVector3C v = object.getLinearVel();
            DVector3C p = object.getPosition();
            double speed = Math.sqrt(v.get0() * v.get0() + v.get1() * v.get1() + v.get2() * v.get2());
            if (!(speed < DIVERGED_SPEED) || !Double.isFinite(p.get0() + p.get1() + p.get2())) {
                throw new SimulationDiverged("object speed " + speed + " m/s at t = " + time + " s");
            }
        }
    }

    /** Switches the bounding-sphere test of hand-object pairs on (the default) or off; for tests. */
    void setBroadPhase(boolean on) {
        broadPhase = on;
    }

    @Override
    public void setAccounting(boolean on) {
        accounting = on ? accounts : null;
    }

    @Override
    public StepAccounting accounting() {
        return accounts;
    }

    // ---- collisions -------------------------------------------------------------------------

    /**
     * Contacts of the object with the hand/arm, the ground and the boxes. The hand's geoms are
     * paired with the object here, in model order, and only when their bounding spheres overlap:
     * a broad phase of about 40 sphere tests instead of an ODE space recomputing every hand
     * geom's bounding box each step. The exact colliders then decide as before.
     */
    private void collide() {
        if (object == null) {
            return;
        }
        DVector3C op = object.getPosition();
        DQuaternionC or = object.getQuaternion();
        objectRotation[0] = or.get0();
        objectRotation[1] = or.get1();
        objectRotation[2] = or.get2();
        objectRotation[3] = or.get3();
        for (int k = 0; k < objectGeoms.size(); k++) {
            DGeom g = objectGeoms.get(k);
            double[] ob = objectBounds.get(k);
            Rotations.rotate(objectRotation, 0, ob, 0, centre, 0);
            double ox = op.get0() + centre[0], oy = op.get1() + centre[1], oz = op.get2() + centre[2];
            for (int i = 0; i < handGeoms.length; i++) {
                int b = handGeomBody[i];
                Rotations.rotate(rotations, 4 * b, handGeomCentre, 3 * i, centre, 3);
                DVector3C bp = bodies[b].getPosition();
                double dx = bp.get0() + centre[3] - ox, dy = bp.get1() + centre[4] - oy, dz = bp.get2() + centre[5] - oz;
                double reach = handGeomRadius[i] + ob[3];
                if (!broadPhase || dx * dx + dy * dy + dz * dz <= reach * reach) {
                    collidePair(g, handGeoms[i]);
                }
            }
            collidePair(g, ground);
            for (int i = 0; i < boxes.size(); i++) {
                collidePair(g, boxes.get(i));
            }
        }
    }

    /** Generates the contacts of one geometry pair, with the paper's per-contact ERP and CFM. */
    private void collidePair(DGeom o1, DGeom o2) {
        boolean cylinderCapsulePair = o1 instanceof DCylinder && o2 instanceof DCapsule
                || o1 instanceof DCapsule && o2 instanceof DCylinder;
        int n = cylinderCapsulePair
                ? cylinderCapsule.dColliderFn(o1, o2, config.maxContactsPerPair(), contactBuffer.getGeomBuffer())
                : OdeHelper.collide(o1, o2, config.maxContactsPerPair(), contactBuffer.getGeomBuffer());
        if (n == 0) {
            return;
        }
        GeomTag t1 = (GeomTag) o1.getData();
        GeomTag t2 = (GeomTag) o2.getData();
        GeomTag other = t1.kind() == Kind.OBJECT ? t2 : t1;
        double erp, cfm;
        if (other.kind() == Kind.HAND) {
            erp = handErp[other.body()];
            cfm = handCfm[other.body()];
        } else {
            erp = staticErp;
            cfm = staticCfm;
            if (other.kind() == Kind.GROUND) {
                touchesGround = true;
            } else {
                touchesBox = true;
            }
        }
        DBody b1 = o1.getBody();
        DBody b2 = o2.getBody();
        for (int i = 0; i < n; i++) {
            DContact c = contactBuffer.get(i);
            c.surface.mode = OdeConstants.dContactSoftERP | OdeConstants.dContactSoftCFM | OdeConstants.dContactApprox1;
            c.surface.mu = config.friction();
            c.surface.soft_erp = erp;
            c.surface.soft_cfm = cfm;
            OdeHelper.createContactJoint(world, contactGroup, c).attach(b1, b2);
            if (other.kind() == Kind.HAND) {
                contacts.add(other.body(), c.geom.depth);
            }
        }
    }

    // ---- bodies -----------------------------------------------------------------------------

    @Override
    public Frame bodyFrame(int body) {
        DBody b = bodies[body];
        Quat r = rotation(b);
        Vec3 origin = vec(b.getPosition()).minus(r.rotate(centreOfMass[body]));
        return new Frame(origin, r);
    }

    @Override
    public Vec3 pointVelocity(int body, Vec3 local) {
        Vec3 rel = local.minus(centreOfMass[body]);
        DVector3 out = new DVector3();
        bodies[body].getRelPointVel(rel.x(), rel.y(), rel.z(), out);
        return vec(out);
    }

    @Override
    public Vec3 angularVelocity(int body) {
        return vec(bodies[body].getAngularVel());
    }

    // ---- the object and the scenery -----------------------------------------------------------

    @Override
    public void spawnObject(ObjectSpec spec, RigidState state) {
        removeObject();
        object = OdeHelper.createBody(world);
        DMass mass = OdeHelper.createMass();
        mass.setMass(spec.mass().mass());
        var i = spec.mass().inertia();
        mass.setI(new DMatrix3(i.xx(), i.xy(), i.xz(), i.xy(), i.yy(), i.yz(), i.xz(), i.yz(), i.zz()));
        mass.setC(new DVector3(0, 0, 0));
        object.setMass(mass);
        for (Shape s : spec.shapes()) {
            DGeom g = createGeom(null, s);
            g.setBody(object);
            applyOffset(g, s, Vec3.ZERO);
            g.setData(new GeomTag(Kind.OBJECT, -1));
            objectGeoms.add(g);
            objectBounds.add(boundingSphere(s, Vec3.ZERO));
        }
        objectSpec = spec;
        setBody(object, state);
        // contact ERP/CFM depend on the two masses (sec. 4.1); static geometry counts as 0 kg
        double m = spec.mass().mass();
        for (Body b : model.bodies()) {
            handErp[b.index()] = config.contactErp(m, b.mass().mass());
            handCfm[b.index()] = config.contactCfm(m, b.mass().mass());
        }
        staticErp = config.contactErp(m, 0);
        staticCfm = config.contactCfm(m, 0);
    }

    private void removeObject() {
        for (DGeom g : objectGeoms) {
            g.destroy();
        }
        objectGeoms.clear();
        objectBounds.clear();
        if (object != null) {
            object.destroy();
            object = null;
            objectSpec = null;
        }
    }

    @Override
    public boolean hasObject() {
        return object != null;
    }

    @Override
    public ObjectSpec objectSpec() {
        requireObject();
        return objectSpec;
    }

    @Override
    public RigidState objectState() {
        requireObject();
        return new RigidState(vec(object.getPosition()), rotation(object), vec(object.getLinearVel()),
                vec(object.getAngularVel()));
    }

    @Override
    public void objectPosition(double[] out) {
        requireObject();
        DVector3C p = object.getPosition();
        out[0] = p.get0();
        out[1] = p.get1();
        out[2] = p.get2();
    }

    private void requireObject() {
        if (object == null) {
            throw new IllegalStateException("no object in the world");
        }
    }

    @Override
    public void addStaticBox(Vec3 center, Vec3 size) {
        DBox box = OdeHelper.createBox(null, size.x(), size.y(), size.z());
        box.setPosition(center.x(), center.y(), center.z());
        box.setData(new GeomTag(Kind.BOX, -1));
        boxes.add(box);
        boxSpecs.add(new WorldSnapshot.StaticBox(center, size));
    }

    @Override
    public List<WorldSnapshot.StaticBox> staticBoxes() {
        return List.copyOf(boxSpecs);
    }

    @Override
    public ContactReport handContacts() {
        return contacts;
    }

    @Override
    public boolean objectTouchesGround() {
        return touchesGround;
    }

    @Override
    public boolean objectTouchesBox() {
        return touchesBox;
    }

    @Override
    public void close() {
        removeObject();
        for (DGeom b : boxes) {
            b.destroy();
        }
        contactGroup.destroy();
        ground.destroy();
        for (DGeom g : handGeoms) {
            g.destroy();
        }
        world.destroy();
    }

    // ---- conversions ------------------------------------------------------------------------

    private static Quat rotation(DBody b) {
        DQuaternionC r = b.getQuaternion();
        return new Quat(r.get0(), r.get1(), r.get2(), r.get3());
    }

    private static Vec3 vec(DVector3C v) {
        return new Vec3(v.get0(), v.get1(), v.get2());
    }
}
