package handsim.sim.ode;

import handsim.kin.Kinematics;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.Body;
import handsim.model.Dof;
import handsim.model.HandModel;
import handsim.model.Joint;
import handsim.model.MassProperties;
import handsim.model.Shape;
import handsim.sim.ObjectSpec;
import handsim.sim.SimConfig;
import java.util.ArrayList;
import java.util.List;
import org.ode4j.math.DMatrix3;
import org.ode4j.math.DQuaternion;
import org.ode4j.math.DVector3;
import org.ode4j.ode.DAMotorJoint;
import org.ode4j.ode.DBallJoint;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DBox;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DHingeJoint;
import org.ode4j.ode.DJoint;
import org.ode4j.ode.DJointGroup;
import org.ode4j.ode.DMass;
import org.ode4j.ode.DPlane;
import org.ode4j.ode.DSpace;
import org.ode4j.ode.DUniversalJoint;
import org.ode4j.ode.DWorld;
import org.ode4j.ode.OdeHelper;


/**
 * The world builder: the arm+hand of a {@link HandModel} as ode4j bodies, geoms and joints in a
 * new world (gravity, solver and damping from the {@link SimConfig}), every body at its
 * zero-configuration place; and the object's body and the static boxes as they are added. The
 * creation order is the engine's constraint order, so it is kept fixed.
 */
final class OdeWorld {

    /**
     * Bounding spheres are grown by this much (m) so that rounding can never hide a touching
     * pair: the margin only decides which pairs the exact colliders test.
     */
    private static final double BOUND_MARGIN = 1e-3;

    enum Kind { HAND, OBJECT, GROUND, BOX }

    /** What a geometry belongs to; stored as the geom's user data. */
    record GeomTag(Kind kind, int body) {
    }

    private final HandModel model;
    final DWorld world;
    final DJointGroup contactGroup;
    final DPlane ground;
    /** The fixed shoulder: a kinematic body that never moves. */
    final DBody torso;
    final DBody[] bodies;
    /** Each body's centre of mass in its own frame (m). */
    final Vec3[] centreOfMass;
    /** The limit motors of the ball joints, by joint index (null for the other joints). */
    final DAMotorJoint[] limitMotors;
    /** Every joint in creation order, a ball joint's limit motor after it. */
    final List<DJoint> joints = new ArrayList<>();
    /** The hand's geoms in model order, with their body and bounding sphere (centre relative to the centre of mass, radius). */
    final DGeom[] handGeoms;
    final int[] handGeomBody;
    final double[] handGeomCentre;
    final double[] handGeomRadius;

    OdeWorld(HandModel model, SimConfig config) {
        this.model = model;
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
        torso = OdeHelper.createBody(world);
        torso.setKinematic();
        bodies = new DBody[n];
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
    }

    /**
     * The thrown object's body at the origin, its geoms and their bounding spheres appended to
     * {@code geoms} and {@code bounds}.
     */
    DBody createObject(ObjectSpec spec, List<DGeom> geoms, List<double[]> bounds) {
        DBody object = OdeHelper.createBody(world);
        object.setMass(mass(spec.mass()));
        for (Shape s : spec.shapes()) {
            DGeom g = createGeom(null, s);
            g.setBody(object);
            applyOffset(g, s, Vec3.ZERO);
            g.setData(new GeomTag(Kind.OBJECT, -1));
            geoms.add(g);
            bounds.add(boundingSphere(s, Vec3.ZERO));
        }
        return object;
    }

    /** A box fixed in the world, centred at {@code center}, of edge lengths {@code size} (m). */
    static DBox createStaticBox(Vec3 center, Vec3 size) {
        DBox box = OdeHelper.createBox(null, size.x(), size.y(), size.z());
        box.setPosition(center.x(), center.y(), center.z());
        box.setData(new GeomTag(Kind.BOX, -1));
        return box;
    }

    /** The engine's mass of {@code m}, about the body's origin at the centre of mass. */
    private static DMass mass(MassProperties m) {
        DMass mass = OdeHelper.createMass();
        mass.setMass(m.mass());
        var i = m.inertia();
        mass.setI(new DMatrix3(i.xx(), i.xy(), i.xz(), i.xy(), i.yy(), i.yz(), i.xz(), i.yz(), i.zz()));
        mass.setC(new DVector3(0, 0, 0));
        return mass;
    }

    /**
     * Creates a body at its zero-configuration place: frame at the joint anchor, world-aligned;
     * its geoms and their bounding spheres are appended to {@code geoms} and {@code bounds}.
     */
    private DBody createBody(Body b, List<DGeom> geoms, List<double[]> bounds) {
        DBody body = OdeHelper.createBody(world);
        Vec3 com = b.mass().com();
        centreOfMass[b.index()] = com;
        body.setMass(mass(b.mass()));
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
    static DGeom createGeom(DSpace space, Shape s) {
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
    static double[] boundingSphere(Shape s, Vec3 com) {
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
    static void applyOffset(DGeom geom, Shape s, Vec3 com) {
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
                joints.add(h);
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
                joints.add(u);
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
                joints.add(ball);
                joints.add(m);
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

    /** Destroys the hand's geoms, the ground, the contact group and the world. */
    void destroy() {
        contactGroup.destroy();
        ground.destroy();
        for (DGeom g : handGeoms) {
            g.destroy();
        }
        world.destroy();
    }
}
