package handsim.cards.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.cards.contact.CollisionMesh.FrictionTable;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The card simulator on small scenes, each against an expectation from first principles. */
@Tag("slow")
class CardPhysicsTest {

    private static final FrictionTable FRICTION = new FrictionTable(0.2, 0.4, 0.4);

    @Test
    void cardDroppedOnAPlaneComesToRestWithoutPenetrating() {
        // A flat card released 2 mm above the ground falls freely (½ g t² reaches 2 mm at 20 ms),
        // IPC stops it: every step must keep every vertex's gap d − ξ > 0, and once resting the
        // barrier balances its weight at a gap inside the activation distance d̂.
        SolverSettings s = CardsTestScenes.settings();
        SoftWorld w = CardsTestScenes.cardOverGround(CardsTestScenes.PES, 0.002, FRICTION);
        SoftSimulator sim = new SoftSimulator(w, s, BoneMotion.STILL);
        SimState st = w.restState();
        double half = CardsTestScenes.PES.thickness() / 2;
        for (int i = 0; i < 30; i++) {
            StepStats step = sim.step(st);
            assertTrue(step.minGap > 0, "contact gap at step " + i + ": " + step.minGap);
            for (int k = 0; k < st.nodeCount(); k++) {
                assertTrue(st.x[3 * k + 2] - half > 0, "vertex " + k + " below the ground at step " + i);
            }
        }
        double vmax = 0;
        double zmax = 0;
        for (int k = 0; k < st.nodeCount(); k++) {
            vmax = Math.max(vmax, Math.abs(st.v[3 * k]) + Math.abs(st.v[3 * k + 1]) + Math.abs(st.v[3 * k + 2]));
            zmax = Math.max(zmax, st.x[3 * k + 2] - half);
        }
        assertTrue(vmax < 1e-3, "at rest after 0.3 s: largest speed " + vmax + " m/s");
        assertTrue(zmax < s.dhat(), "resting within d̂ of the ground: highest gap " + zmax);
    }

    @Test
    void bentCardReturnsFlat() {
        // Card stock bent into z = c x² (4 mm of sag over the card) and released without gravity:
        // the hinge energy has its only minimum at the flat rest shape and implicit Euler
        // dissipates, so the card straightens; the remaining deviation from its mean plane must
        // fall below 2 % of the initial one within 0.5 s (bending period ~ 2π/140 s for 0.25 mm
        // card stock, many periods of numerical damping at h = 10 ms).
        SolverSettings s = CardsTestScenes.withGravity(CardsTestScenes.settings(), 0);
        SoftWorld w = new SoftWorld.Builder().friction(FRICTION)
                .card("card", handsim.cards.mesh.CardMesher.generate(0.0889, 0.0635, 11, 6, new boolean[4]),
                        CardsTestScenes.CARD_STOCK, SoftWorld.Placement.at(0, 0, 0))
                .build();
        SimState st = w.restState();
        double c = 0.004 / (0.04445 * 0.04445);
        for (int k = 0; k < st.nodeCount(); k++) {
            double x = st.x[3 * k];
            st.x[3 * k + 2] = c * x * x;
        }
        double before = deviationFromMeanPlane(st);
        SoftSimulator sim = new SoftSimulator(w, s, BoneMotion.STILL);
        for (int i = 0; i < 50; i++) {
            sim.step(st);
        }
        double after = deviationFromMeanPlane(st);
        assertTrue(after < 0.02 * before, "deviation from flat " + after + " m, started at " + before + " m");
    }

    /** Largest |z − mean z| (the card moves only along z here by symmetry). */
    private static double deviationFromMeanPlane(SimState st) {
        double mean = 0;
        int n = st.nodeCount();
        for (int k = 0; k < n; k++) {
            mean += st.x[3 * k + 2] / n;
        }
        double dev = 0;
        for (int k = 0; k < n; k++) {
            dev = Math.max(dev, Math.abs(st.x[3 * k + 2] - mean));
        }
        return dev;
    }

    /** Bones close in by 100 µm over 0.1 s (gravity ramping on from 0.05 s to 0.1 s), hold, then open by 2 mm in 0.3–0.35 s. */
    private static BoneMotion pinchThenOpen() {
        return (finger, t, out) -> {
            double sign = finger == 0 ? 1 : -1;
            double close = 1e-4 * ease(t, 0, 0.05);
            double open = 2e-3 * ease(t, 0.3, 0.35);
            out[0] = 0;
            out[1] = sign * (close - open);
            out[2] = 0;
        };
    }

    private static double ease(double t, double a, double b) {
        return t <= a ? 0 : t >= b ? 1 : 0.5 * (1 - Math.cos(Math.PI * (t - a) / (b - a)));
    }

    private static SoftSimulator pinchSimulator(SoftWorld w, SolverSettings s) {
        return new SoftSimulator(w, s, pinchThenOpen()).withGravityScale(t -> ease(t, 0.05, 0.1));
    }

    @Test
    void pinchHoldsACardByFrictionAndLosesItWhenItOpens() {
        // Gravity acts in the card's plane, so only friction holds it: static friction 2 μ N
        // exceeds m g = 0.88 g x 9.81 = 8.6 mN once the skins press with N > 11 mN (μ = 0.4).
        // Held from 0.1 s to 0.3 s, the card may creep only by IPC's smoothed static friction
        // (slip below εv h per step): less than 1 mm. Opened at 0.3–0.35 s, it falls freely:
        // from 0.35 s to 0.5 s it drops at least 80 % of ½ g t² = 110 mm.
        SolverSettings s = CardsTestScenes.settings();
        SoftWorld w = CardsTestScenes.pinchedCard(CardsTestScenes.PES, 5e-5, FRICTION);
        SoftSimulator sim = pinchSimulator(w, s);
        SimState st = w.restState();
        double z0 = CardsTestScenes.meanZ(w, st, "card");
        for (int i = 0; i < 30; i++) {
            StepStats step = sim.step(st);
            assertTrue(step.minGap > 0, "gap at step " + i);
        }
        double held = CardsTestScenes.meanZ(w, st, "card");
        assertTrue(z0 - held < 1e-3, "held card slid " + (z0 - held) + " m");
        for (int i = 30; i < 35; i++) {
            sim.step(st);
        }
        double released = CardsTestScenes.meanZ(w, st, "card");
        for (int i = 35; i < 50; i++) {
            StepStats step = sim.step(st);
            assertTrue(step.minGap > 0, "gap at step " + i);
        }
        double drop = released - CardsTestScenes.meanZ(w, st, "card");
        double freeFall = 0.5 * 9.81 * 0.15 * 0.15;
        assertTrue(drop > 0.8 * freeFall, "released card dropped " + drop + " m, free fall " + freeFall + " m");
    }

    @Test
    void sameInputsGiveBitIdenticalTrajectoriesOnOneOrTwoThreads() {
        // Nothing in a step depends on time, thread scheduling or hash order: assembly is split
        // into two fixed halves summed in a fixed order whether or not they run in parallel.
        SoftWorld w = CardsTestScenes.pinchedCard(CardsTestScenes.PES, 5e-5, FRICTION);
        SimState a = run(w, CardsTestScenes.withParallel(CardsTestScenes.settings(), true), 15);
        SimState b = run(w, CardsTestScenes.withParallel(CardsTestScenes.settings(), true), 15);
        SimState c = run(w, CardsTestScenes.withParallel(CardsTestScenes.settings(), false), 15);
        assertTrue(a.sameAs(b), "two runs differ");
        assertTrue(a.sameAs(c), "parallel and sequential assembly differ");
    }

    private static SimState run(SoftWorld w, SolverSettings s, int steps) {
        SoftSimulator sim = pinchSimulator(w, s);
        SimState st = w.restState();
        for (int i = 0; i < steps; i++) {
            sim.step(st);
        }
        return st;
    }

    @Test
    void checkpointResumesBitForBit() throws IOException {
        // A checkpoint holds the whole changing state (positions, velocities, time, barrier
        // stiffness); bone targets and lagged friction follow from it, so a run resumed from the
        // bytes continues exactly as the uninterrupted run.
        SolverSettings s = CardsTestScenes.settings();
        SoftWorld w = CardsTestScenes.pinchedCard(CardsTestScenes.PES, 5e-5, FRICTION);
        SoftSimulator sim = pinchSimulator(w, s);
        SimState st = w.restState();
        for (int i = 0; i < 10; i++) {
            sim.step(st);
        }
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        st.write(new DataOutputStream(bytes));
        for (int i = 0; i < 8; i++) {
            sim.step(st);
        }
        SimState resumed = SimState.read(new DataInputStream(new ByteArrayInputStream(bytes.toByteArray())));
        assertEquals(10, resumed.steps);
        SoftSimulator fresh = pinchSimulator(w, s);
        for (int i = 0; i < 8; i++) {
            fresh.step(resumed);
        }
        assertTrue(st.sameAs(resumed), "resumed run differs from the uninterrupted one");
    }
}
