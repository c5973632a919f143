package handsim.sim.ode;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.model.HandModel;
import handsim.sim.SimConfig;
import handsim.sim.WorldState;
import handsim.sim.island.IslandStep.AssembledRow;
import handsim.task.HeldBallScenario;
import handsim.task.ServoLoop;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.ode4j.ode.internal.DxBody;
import org.ode4j.ode.internal.DxWorld;
import org.ode4j.ode.internal.joints.DxJoint;
import org.ode4j.ode.internal.joints.DxJointNode;

/**
 * handsim's island step against ode4j's quickStep, the reference: the same rows, in the same
 * order, for a held ball (contacts on several fingers, joints at their stops), and the same step
 * to rounding.
 */
@Tag("fast")
class HandsimStepperTest {

    private final HandModel m = TestSupport.model();
    private final SimConfig config = TestSupport.simConfig();

    /**
     * The held ball 0.6 s after the throw into the palm (the fingers closed on it 0.3 s
     * earlier), stepped by handsim's step.
     */
    private WorldState heldBall() {
        try (OdeSimulator sim = new OdeSimulator(m, config.withStepper(SimConfig.Stepper.HANDSIM))) {
            HeldBallScenario scenario = new HeldBallScenario(new ServoLoop(sim, TestSupport.pd(m)), TestSupport.object("sphere"), 0.2, 1);
            for (int i = 0; i < 3000; i++) {
                scenario.step();
            }
            assertTrue(sim.handContacts().points() >= 3, "contacts of the held ball: " + sim.handContacts().points());
            return sim.captureState();
        }
    }

    /**
     * A ball resting in the open palm while the servos drive four joints 2 degrees past their
     * stops (a ball joint's Euler angle, a hinge, each axis of universal joints), 0.3 s after
     * the ball was dropped there.
     */
    private WorldState pressedAgainstStops() {
        try (OdeSimulator sim = new OdeSimulator(m, config.withStepper(SimConfig.Stepper.HANDSIM))) {
            ServoLoop loop = new ServoLoop(sim, TestSupport.pd(m));
            double[] pose = m.poseVector("neutral");
            m.pose("open").applyTo(pose);
            double past = Math.toRadians(2);
            pose[m.dof("wrist_deviation").index()] = m.dof("wrist_deviation").upper() + past;
            pose[m.dof("index_pip_flexion").index()] = m.dof("index_pip_flexion").lower() - past;
            pose[m.dof("index_mcp_abduction").index()] = m.dof("index_mcp_abduction").upper() + past;
            pose[m.dof("thumb_mcp_flexion").index()] = m.dof("thumb_mcp_flexion").upper() + past;
            sim.reset(pose, 7);
            System.arraycopy(pose, 0, loop.targets(), 0, pose.length);
            handsim.kin.Frame palm = new handsim.kin.Kinematics(m).siteFrame(m.site("palm_center"), pose);
            handsim.sim.ObjectSpec ball = TestSupport.object("sphere");
            handsim.math.Vec3 above = palm.origin().plus(palm.rotation().yAxis().negate().times(ball.halfThickness() + 0.002));
            sim.spawnObject(ball, new handsim.sim.RigidState(above, handsim.math.Quat.IDENTITY, handsim.math.Vec3.ZERO,
                    handsim.math.Vec3.ZERO));
            for (int i = 0; i < 1500; i++) {
                loop.step();
            }
            assertTrue(sim.handContacts().any(), "the ball rests in the palm");
            return sim.captureState();
        }
    }

    @Test
    void rowsAreQuickStepsRowsInQuickStepsOrderToRounding() {
        assertSameRows(heldBall(), 9, 0);
        assertSameRows(pressedAgainstStops(), 3, 4);
    }

    /** Compares the rows of {@code state}, which must have at least so many contact rows and stop rows. */
    private void assertSameRows(WorldState state, int minContactRows, int minStopRows) {
        List<AssembledRow> mine;
        try (OdeSimulator sim = new OdeSimulator(m, config.withStepper(SimConfig.Stepper.HANDSIM))) {
            sim.restoreState(state);
            sim.collideOnly();
            mine = sim.assembledRows();
            sim.clearContacts();
        }
        List<double[]> reference = new ArrayList<>();
        List<DxJoint> referenceJoints = new ArrayList<>();
        try (OdeSimulator sim = new OdeSimulator(m, config.withStepper(SimConfig.Stepper.ODE4J))) {
            sim.restoreState(state);
            sim.collideOnly();
            quickStepRows((DxWorld) sim.world().world, config.timeStep(), reference, referenceJoints);
            sim.clearContacts();
        }
        assertEquals(reference.size(), mine.size(), "rows");
        int contactRows = 0, stopRows = 0, sparseRows = 0;
        for (int r = 0; r < mine.size(); r++) {
            AssembledRow a = mine.get(r);
            double[] b = reference.get(r);
            String where = "row " + r + " (" + referenceJoints.get(r).getClass().getSimpleName() + ", joint " + a.joint() + ")";
            // to rounding: Jacobian entries are unit vectors and lever arms under a metre; rhs is
            // fps erp times a position or angle error, and the stops' angles come from ode4j's
            // quaternions there and from Kinematics here (each exact to about 1e-15 rad)
            for (int k = 0; k < 6; k++) {
                assertEquals(b[k], a.j1()[k], 1e-12, where + " J1[" + k + "]");
                assertEquals(b[8 + k], a.j2()[k], 1e-12, where + " J2[" + k + "]");
            }
            assertEquals(b[6], a.rhs(), 1e-9 * Math.max(1, Math.abs(b[6])), where + " rhs");
            assertEquals(b[7], a.cfm(), 1e-12 * b[7], where + " cfm");
            assertEquals(b[14], a.lo(), 0.0, where + " lo");
            assertEquals(b[15], a.hi(), 0.0, where + " hi");
            assertEquals((int) b[16], a.findex(), where + " findex");
            // the zeros the assembly declares, which the sweep leaves out, are zeros
            for (int z : a.zeros()) {
                assertTrue(a.j1()[z] == 0 && a.j2()[z] == 0 && b[z] == 0 && b[8 + z] == 0, where + " declares J[" + z + "] zero");
            }
            sparseRows += a.zeros().length > 0 ? 1 : 0;
            contactRows += a.joint() < 0 ? 1 : 0;
            stopRows += b[14] == 0 ^ b[15] == 0 && a.joint() >= 0 ? 1 : 0;
        }
        // the state must exercise contacts, friction and stops
        assertTrue(contactRows >= minContactRows, "contact rows " + contactRows);
        assertTrue(stopRows >= minStopRows, "stop rows " + stopRows);
        assertTrue(sparseRows >= mine.size() / 2, sparseRows + " of " + mine.size() + " rows declare zeros: the joints' rows at least");
    }

    /**
     * ode4j's rows of every joint of {@code world} in the order its quickStep solves them: the
     * islands searched from the bodies in list order, depth first through each body's joint list
     * (ODE's dxBuildIslands), each joint's rows from its own getInfo1/getInfo2 on a row prepared
     * as quickStep prepares it (J 0, rhs 0, cfm the world's, unbounded, no friction index). Each
     * row: J1 (6), rhs, cfm, J2 (6), lo, hi, the friction index relative to the joint.
     */
    static void quickStepRows(DxWorld world, double h, List<double[]> out, List<DxJoint> owners) {
        Map<Object, Boolean> tagged = new IdentityHashMap<>();
        for (DxBody start = world.firstbody.get(); start != null; start = (DxBody) start.getNext()) {
            if (tagged.containsKey(start)) {
                continue;
            }
            tagged.put(start, true);
            List<DxBody> stack = new ArrayList<>();
            DxBody b = start;
            while (true) {
                for (DxJointNode n = b.firstjoint.get(); n != null; n = n.next) {
                    if (tagged.containsKey(n.joint)) {
                        continue;
                    }
                    tagged.put(n.joint, true);
                    appendRows(n.joint, world, h, out, owners);
                    if (n.body != null && !tagged.containsKey(n.body)) {
                        tagged.put(n.body, true);
                        stack.add(n.body);
                    }
                }
                if (stack.isEmpty()) {
                    break;
                }
                b = stack.remove(stack.size() - 1);
            }
        }
    }

    private static void appendRows(DxJoint joint, DxWorld world, double h, List<double[]> out, List<DxJoint> owners) {
        DxJoint.Info1 info = new DxJoint.Info1();
        joint.getInfo1(info);
        int rows = info.getM();
        double[] j = new double[16 * rows];
        int[] findex = new int[rows];
        for (int r = 0; r < rows; r++) {
            j[16 * r + 7] = world.getCFM();
            j[16 * r + 14] = Double.NEGATIVE_INFINITY;
            j[16 * r + 15] = Double.POSITIVE_INFINITY;
            findex[r] = -1;
        }
        joint.getInfo2(1 / h, world.getERP(), 16, j, 0, j, 8, 16, j, 6, j, 14, findex, 0);
        for (int r = 0; r < rows; r++) {
            double[] row = new double[17];
            System.arraycopy(j, 16 * r, row, 0, 16);
            row[16] = findex[r];
            out.add(row);
            owners.add(joint);
        }
    }

    @Test
    void oneStepIsQuickStepsToRounding() {
        assertSameStep(heldBall());
        assertSameStep(pressedAgainstStops());
    }

    private void assertSameStep(WorldState state) {
        WorldState mine, reference;
        try (OdeSimulator sim = new OdeSimulator(m, config.withStepper(SimConfig.Stepper.HANDSIM))) {
            sim.restoreState(state);
            sim.step();
            mine = sim.captureState();
        }
        try (OdeSimulator sim = new OdeSimulator(m, config.withStepper(SimConfig.Stepper.ODE4J))) {
            sim.restoreState(state);
            sim.step();
            reference = sim.captureState();
        }
        // the same rows in the same order, the same random reorder (the generator drew as often)
        assertEquals(reference.randomSeed(), mine.randomSeed(), "the row shuffle drew the same numbers");
        double[] a = mine.bodies(), b = reference.bodies();
        for (int i = 0; i < a.length; i++) {
            // positions to 1e-15 m, velocities to 1e-10 (m/s, rad/s): rounding of sums in another order
            assertEquals(b[i], a[i], 1e-10 * Math.max(1, Math.abs(b[i])), "body state " + i / WorldState.PER_BODY + "." + i % WorldState.PER_BODY);
        }
    }
}
