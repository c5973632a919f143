package handsim.sim.ode;

import handsim.kin.Rotations;
import handsim.model.Body;
import handsim.model.HandModel;
import handsim.sim.ContactReport;
import handsim.sim.SimConfig;
import handsim.sim.island.ContactPoints;
import handsim.sim.ode.OdeWorld.GeomTag;
import handsim.sim.ode.OdeWorld.Kind;
import java.util.List;
import org.ode4j.math.DQuaternionC;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DCapsule;
import org.ode4j.ode.DContact;
import org.ode4j.ode.DContactBuffer;
import org.ode4j.ode.DContactGeomBuffer;
import org.ode4j.ode.DCylinder;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.OdeConstants;
import org.ode4j.ode.OdeHelper;

/**
 * Contact generation, the canonical collide step before quickStep: the object against the
 * hand/arm, the ground and the static boxes (the hand does not collide with itself), each contact
 * with the ERP and CFM of the paper's compliant contact model from the masses of its two bodies
 * (sec. 4.1), made an ode4j contact joint for quickStep or, for handsim's step, handed to its
 * {@link ContactPoints} as geometry; the hand contacts reported per body and their depth.
 */
final class OdeContacts {

    private final SimConfig config;
    private final OdeWorld w;
    private final DContactBuffer contactBuffer;
    /** The colliders' view of {@link #contactBuffer}; ode4j makes a new one per call of getGeomBuffer. */
    private final DContactGeomBuffer geomBuffer;
    private final CylinderCapsuleCollider cylinderCapsule = new CylinderCapsuleCollider();
    /** Contact ERP and CFM of the object against each hand body, and against static geometry. */
    private final double[] handErp;
    private final double[] handCfm;
    private double staticErp;
    private double staticCfm;
    final ContactReport report = new ContactReport();
    boolean touchesGround;
    boolean touchesBox;
    /** Whether hand-object pairs pass the bounding-sphere test first (off only in tests). */
    boolean broadPhase = true;
    private final double[] objectRotation = new double[4];
    private final double[] centre = new double[6];
    /** Where handsim's step takes the contacts, null when ode4j's quickStep steps (contact joints). */
    private final ContactPoints points;
    /** The object's body index in {@link #points}. */
    private final int objectIndex;

    OdeContacts(OdeWorld w, SimConfig config, int bodyCount, ContactPoints points, int objectIndex) {
        this.w = w;
        this.config = config;
        this.points = points;
        this.objectIndex = objectIndex;
        contactBuffer = new DContactBuffer(config.maxContactsPerPair());
        geomBuffer = contactBuffer.getGeomBuffer();
        handErp = new double[bodyCount];
        handCfm = new double[bodyCount];
    }

    /** The contact ERP and CFM of an object of {@code objectMass} kg; static geometry counts as 0 kg. */
    void objectMass(double objectMass, HandModel model) {
        for (Body b : model.bodies()) {
            handErp[b.index()] = config.contactErp(objectMass, b.mass().mass());
            handCfm[b.index()] = config.contactCfm(objectMass, b.mass().mass());
        }
        staticErp = config.contactErp(objectMass, 0);
        staticCfm = config.contactCfm(objectMass, 0);
    }

    /**
     * Contacts of the object with the hand/arm, the ground and the boxes. The hand's geoms are
     * paired with the object here, in model order, and only when their bounding spheres overlap:
     * a broad phase of about 40 sphere tests instead of an ODE space recomputing every hand
     * geom's bounding box each step. The exact colliders then decide as before.
     */
    void collide(DBody object, List<DGeom> objectGeoms, List<double[]> objectBounds, List<DGeom> boxes, double[] rotations) {
        if (object == null) {
            return;
        }
        DGeom[] handGeoms = w.handGeoms;
        int[] handGeomBody = w.handGeomBody;
        double[] handGeomCentre = w.handGeomCentre;
        double[] handGeomRadius = w.handGeomRadius;
        DBody[] bodies = w.bodies;
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
            collidePair(g, w.ground);
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
                ? cylinderCapsule.dColliderFn(o1, o2, config.maxContactsPerPair(), geomBuffer)
                : OdeHelper.collide(o1, o2, config.maxContactsPerPair(), geomBuffer);
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
            if (points != null) {
                // body 1 is the object's (o1 is always an object geom), body 2 the hand's or none
                DVector3C p = c.geom.pos, normal = c.geom.normal;
                points.add(objectIndex, other.kind() == Kind.HAND ? other.body() : -1, p.get0(), p.get1(), p.get2(),
                        normal.get0(), normal.get1(), normal.get2(), c.geom.depth, erp, cfm, config.friction());
            } else {
                c.surface.mode = OdeConstants.dContactSoftERP | OdeConstants.dContactSoftCFM | OdeConstants.dContactApprox1;
                c.surface.mu = config.friction();
                c.surface.soft_erp = erp;
                c.surface.soft_cfm = cfm;
                OdeHelper.createContactJoint(w.world, w.contactGroup, c).attach(b1, b2);
            }
            if (other.kind() == Kind.HAND) {
                report.add(other.body(), c.geom.depth);
            }
        }
    }
}
