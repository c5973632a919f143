package handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.kin.Frame;
import handsim.kin.Kinematics;
import handsim.math.Vec3;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The shipped model against the paper's and SPEC's figures (sources in models/arm_hand.json). */
@Tag("fast")
class ArmHandModelTest {

    private final HandModel m = TestSupport.model();

    @Test
    void has32DofWithTheDocumentedBreakdown() {
        assertEquals(32, m.dofCount());
        assertEquals(32, m.dofBreakdown().get("total"));
        int byJoint = m.joints().stream().mapToInt(Joint::dofCount).sum();
        assertEquals(32, byJoint);
    }

    @Test
    void namesResolve() {
        for (String body : List.of("upper_arm", "forearm", "palm", "index_distal", "thumb_distal")) {
            assertEquals(body, m.body(body).name());
        }
        assertEquals("elbow_flexion", m.dof("elbow_flexion").name());
        assertEquals(JointType.BALL, m.joint("shoulder").type());
        assertEquals(-1, m.joint("shoulder").parent());
        assertEquals(m.body("palm").index(), m.site("palm_center").body());
        for (String pose : ModelLoader.REQUIRED_POSES) {
            assertTrue(m.poses().containsKey(pose), pose);
        }
    }

    @Test
    void segmentMassesAreThoseOfA75kgMale() {
        // de Leva (1996) fractions of 75 kg: upper arm 2.03, forearm 1.22, hand 0.46 kg
        assertEquals(2.03, m.body("upper_arm").mass().mass(), 1e-9);
        assertEquals(1.22, m.body("forearm").mass().mass(), 1e-9);
        double hand = m.drivenMass(m.joint("wrist").index());
        assertEquals(0.46, hand, 0.01);
        assertEquals(3.71, m.totalMass(), 0.01);
    }

    @Test
    void segmentLengthsAreThoseOfThe50thPercentile() {
        Frame[] zero = new Kinematics(m).forward(new double[m.dofCount()]);
        Vec3 shoulder = zero[m.body("upper_arm").index()].origin();
        Vec3 elbow = zero[m.body("forearm").index()].origin();
        // Huston (2009): upper arm 0.361 m
        assertEquals(0.361, shoulder.distance(elbow), 1e-6);
        // forearm + hand 0.483 m: elbow to the middle fingertip in the anatomical position
        Body distal = m.body("middle_distal");
        Shape.Capsule tip = (Shape.Capsule) distal.shapes().get(0);
        Vec3 fingertip = zero[distal.index()].pointToWorld(tip.b()).plus(new Vec3(0, -tip.radius(), 0));
        assertEquals(0.483, elbow.distance(fingertip), 0.01);
    }

    @Test
    void limitsAreHumanAndTorquesClampToStrength() {
        Dof elbow = m.dof("elbow_flexion");
        assertEquals(0, Math.toDegrees(elbow.lower()), 1e-9);
        assertEquals(150, Math.toDegrees(elbow.upper()), 1e-9);
        for (Dof d : m.dofs()) {
            assertTrue(d.lower() < d.upper(), d.name());
            assertTrue(d.torqueMin() < 0 && d.torqueMax() > 0, d.name());
            // no human joint is stronger than the shoulder (~90 N m)
            assertTrue(d.torqueMax() <= 90 && -d.torqueMin() <= 90, d.name());
        }
        assertEquals(12.2, m.dof("wrist_flexion").clampTorque(100), 1e-12);
        assertEquals(-7.1, m.dof("wrist_flexion").clampTorque(-100), 1e-12);
    }

    @Test
    void posesLieInsideTheLimits() {
        for (Pose p : m.poses().values()) {
            for (int i = 0; i < p.dofs().length; i++) {
                assertEquals(0, m.dofs().get(p.dofs()[i]).limitExcess(p.angles()[i]), 1e-12, p.name());
            }
        }
    }
}
