package handsim.sim.ode;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.kin.Frame;
import handsim.math.RandomGeometry;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.sim.ContactReport;
import handsim.sim.ObjectSpec;
import handsim.sim.RigidState;
import handsim.sim.SimConfig;
import handsim.task.HeldBallScenario;
import handsim.task.ServoLoop;
import java.lang.management.ManagementFactory;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The engine adapter's per-step path: the collision broad phase and its allocation, with either stepper. */
@Tag("fast")
class OdeSimulatorStepTest {

    private final HandModel m = TestSupport.model();
    private final SimConfig config = TestSupport.simConfig();

    @Test
    void boundingSphereBroadPhaseLosesNoContact() {
        SplittableRandom rng = new SplittableRandom(7);
        ObjectSpec[] objects = {TestSupport.object("sphere"), TestSupport.object("can"), TestSupport.object("cuboid"),
            TestSupport.object("club")};
        handsim.kin.Kinematics kin = new handsim.kin.Kinematics(m);
        int touching = 0;
        try (OdeSimulator filtered = new OdeSimulator(m, config); OdeSimulator all = new OdeSimulator(m, config)) {
            all.setBroadPhase(false);
            for (int trial = 0; trial < 200; trial++) {
                double[] pose = TestSupport.randomPose(m, rng, 0.05);
                ObjectSpec object = objects[trial % 4];
                // somewhere within 12 cm of a random body's frame origin, randomly turned
                int body = rng.nextInt(m.bodyCount());
                Frame f = kin.bodyFrame(body, pose);
                Vec3 at = f.origin().plus(RandomGeometry.randomUnit(rng).times(0.12 * rng.nextDouble()));
                RigidState s = new RigidState(at, RandomGeometry.randomRotation(rng), Vec3.ZERO, Vec3.ZERO);
                for (OdeSimulator sim : new OdeSimulator[] {filtered, all}) {
                    sim.reset(pose, trial);
                    sim.spawnObject(object, s);
                    sim.step();
                }
                ContactReport a = filtered.handContacts(), b = all.handContacts();
                // same pairs reach the exact colliders in the same order: identical contacts
                assertEquals(b.points(), a.points(), "contact points, trial " + trial);
                assertEquals(b.bodyMask(), a.bodyMask(), "bodies touched, trial " + trial);
                assertEquals(b.maxDepth(), a.maxDepth(), 0.0, "deepest penetration, trial " + trial);
                touching += b.any() ? 1 : 0;
            }
        }
        // the placements must exercise the colliders: many touch, many do not
        assertTrue(touching > 40 && touching < 190, "trials with hand contact: " + touching);
    }

    @Test
    void heldBallStepLoopAllocatesAtMost64BytesPerStepBesidesTheEngine() {
        var threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        try (OdeSimulator sim = new OdeSimulator(m, config)) {
            HeldBallScenario scenario = new HeldBallScenario(new ServoLoop(sim, TestSupport.pd(m)), TestSupport.object("sphere"), 0.2, 1);
            // through the catch to the held ball: contacts every step from here on
            for (int i = 0; i < 3000; i++) {
                scenario.step();
            }
            sim.setAccounting(true);
            int steps = 2500;
            long engine0 = sim.accounting().engineBytes();
            long bytes0 = threads.getCurrentThreadAllocatedBytes();
            for (int i = 0; i < steps; i++) {
                scenario.step();
            }
            long all = threads.getCurrentThreadAllocatedBytes() - bytes0;
            long engine = sim.accounting().engineBytes() - engine0;
            assertTrue(sim.handContacts().any(), "the ball is held");
            // the bound for the step loop; ode4j's own arena and contact joints are counted apart
            assertTrue((all - engine) / (double) steps <= 64,
                    "handsim allocated " + (all - engine) / (double) steps + " bytes per step (ode4j " + engine / (double) steps + ")");
        }
    }

    @Test
    void handsimsStepAllocatesNothing() {
        try (OdeSimulator sim = new OdeSimulator(m, config.withStepper(SimConfig.Stepper.HANDSIM))) {
            HeldBallScenario scenario = new HeldBallScenario(new ServoLoop(sim, TestSupport.pd(m)), TestSupport.object("sphere"), 0.2, 1);
            // through the catch to the held ball: its arrays have grown to the most rows and contacts
            for (int i = 0; i < 3000; i++) {
                scenario.step();
            }
            sim.setAccounting(true);
            int steps = 2500;
            long solver0 = sim.accounting().solverBytes();
            for (int i = 0; i < steps; i++) {
                scenario.step();
            }
            long solver = sim.accounting().solverBytes() - solver0;
            assertTrue(sim.handContacts().any(), "the ball is held");
            // every array is allocated once and reused: nothing per step, from the first steps on
            // (ode4j's colliders allocate until the JIT has compiled them; BenchCommandTest bounds the whole loop)
            assertEquals(0, solver, "handsim's step allocated " + solver + " bytes in " + steps + " steps");
        }
    }
}
