package handsim.cards.sim;

import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.cards.contact.CollisionMesh.FrictionTable;
import handsim.cards.contact.ContactSet;
import handsim.cards.contact.Friction;
import handsim.cards.energy.Energy;
import handsim.cards.energy.FiniteDifference;
import handsim.cards.energy.HessianSink;
import handsim.cards.mesh.CardMesher;
import java.util.Random;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Finite-difference checks of the whole incremental potential of a step, E = inertia + h²
 * elasticity + barrier + friction, on two small cards touching each other and the ground, so
 * that the barrier (face–vertex, edge–vertex, edge–edge and ground contacts) and the friction
 * (both below and above the smoothing slip εv h) are all active.
 */
@Tag("fast")
class PotentialDerivativesTest {

    @Test
    void incrementalPotentialDerivativesMatchFiniteDifferences() {
        SolverSettings s = CardsTestScenes.settings();
        double t = CardsTestScenes.PES.thickness();
        double[] rot = rotationZ(0.3);
        SoftWorld w = new SoftWorld.Builder().friction(new FrictionTable(0.2, 0.4, 0.4))
                .card("lower", CardMesher.generate(0.02, 0.015, 2, 2, new boolean[4]), CardsTestScenes.PES,
                        SoftWorld.Placement.at(0, 0, t / 2 + 4e-6))
                .card("upper", CardMesher.generate(0.02, 0.015, 2, 2, new boolean[4]), CardsTestScenes.PES,
                        new SoftWorld.Placement(rot, new double[] {0.002, 0.001, 1.5 * t + 1e-5}))
                .ground(0).build();
        Random rng = new Random(7);
        double[] x = w.restPositions();
        for (int i = 0; i < x.length; i++) {
            x[i] += 3e-7 * rng.nextGaussian();
        }
        ContactSet contacts = new ContactSet(w.collision(), s.dhat(), s.hashCell());
        contacts.build(x);
        assertTrue(contacts.size() > 10, "contacts active: " + contacts.size());
        // friction lagged at a start shifted tangentially: slips of about 10 and 0.1 x εv h
        double h = s.timeStep();
        double[] start = x.clone();
        for (int k = 0; k < start.length / 3; k++) {
            double shift = k < w.body("upper").firstNode() ? 1e-7 : 1e-4;
            start[3 * k] -= shift;
        }
        Friction friction = new Friction(s.frictionEpsV());
        double kappa = 1e4;
        contacts.build(start);
        friction.lag(contacts, start, kappa, h);
        contacts.build(x);
        assertTrue(friction.size() > 10, "friction contacts: " + friction.size());
        IncrementalPotential potential = new IncrementalPotential(w, contacts, friction, h, false);
        double[] v = new double[x.length];
        for (int i = 0; i < v.length; i++) {
            v[i] = 0.01 * rng.nextGaussian();
        }
        potential.prepare(start, v, s.gravity(), kappa);
        // each part contributes at x
        assertTrue(potential.inertia(x) > 0 && contacts.energy(x, kappa) > 0 && friction.energy(x) > 0);
        Energy adapter = new Energy() {
            @Override
            public int elementCount() {
                return 1;
            }

            @Override
            public double value(double[] p, int from, int to) {
                return potential.value(p);
            }

            @Override
            public void addGradient(double[] p, int from, int to, double[] g) {
                double[] gg = new double[g.length];
                potential.gradient(p, gg);
                for (int i = 0; i < g.length; i++) {
                    g[i] += gg[i];
                }
            }

            @Override
            public void addHessian(double[] p, int from, int to, HessianSink sink, boolean project) {
                potential.hessian(p, sink, project);
            }

            @Override
            public Energy workspaceCopy() {
                return this;
            }
        };
        FiniteDifference.check(adapter, x, 1e-10, 1e-5);
    }

    private static double[] rotationZ(double a) {
        double c = Math.cos(a);
        double sn = Math.sin(a);
        return new double[] {c, -sn, 0, sn, c, 0, 0, 0, 1};
    }
}
