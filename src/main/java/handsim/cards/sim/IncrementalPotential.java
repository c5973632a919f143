package handsim.cards.sim;

import handsim.cards.contact.ContactSet;
import handsim.cards.contact.Friction;
import handsim.cards.energy.Energy;
import handsim.cards.energy.HessianSink;

/**
 * The incremental potential of one implicit Euler step (IPC, Li et al. 2020, eq. 3):
 * E(x) = ½ ‖x − x̃‖²_M + h² Ψ(x) + κ Σ b + h² D(x) over all nodes (bone nodes carry no inertia
 * term: they are not unknowns). The contact set is whatever was last built; the simulator
 * rebuilds it at every configuration it evaluates.
 */
public final class IncrementalPotential implements Energy {

    private final SoftWorld world;
    private final ContactSet contacts;
    private final Friction friction;
    private final double h;
    private final double[] xTilde;
    private double kappa;

    IncrementalPotential(SoftWorld world, ContactSet contacts, Friction friction, double timeStep) {
        this.world = world;
        this.contacts = contacts;
        this.friction = friction;
        this.h = timeStep;
        this.xTilde = new double[3 * world.nodeCount()];
    }

    /** x̃ = x_t + h v_t + h² g, and the barrier stiffness of the step. */
    void prepare(double[] xt, double[] v, double[] gravity, double kappa) {
        for (int i = 0; i < xTilde.length / 3; i++) {
            for (int c = 0; c < 3; c++) {
                xTilde[3 * i + c] = xt[3 * i + c] + h * v[3 * i + c] + h * h * gravity[c];
            }
        }
        this.kappa = kappa;
    }

    void setKappa(double kappa) {
        this.kappa = kappa;
    }

    /** Inertia ½‖x − x̃‖²_M over the free nodes. */
    double inertia(double[] x) {
        double e = 0;
        for (int i = 0; i < xTilde.length / 3; i++) {
            if (world.dirichlet[i]) {
                continue;
            }
            double d0 = x[3 * i] - xTilde[3 * i];
            double d1 = x[3 * i + 1] - xTilde[3 * i + 1];
            double d2 = x[3 * i + 2] - xTilde[3 * i + 2];
            e += 0.5 * world.mass[i] * (d0 * d0 + d1 * d1 + d2 * d2);
        }
        return e;
    }

    /** Ψ(x): the elastic energies. */
    double elastic(double[] x) {
        double e = 0;
        for (Energy term : world.elasticEnergies()) {
            e += term.value(x);
        }
        return e;
    }

    @Override
    public double value(double[] x) {
        double barrier = contacts.energy(x, kappa);
        if (barrier == Double.POSITIVE_INFINITY) {
            return barrier;
        }
        return inertia(x) + h * h * elastic(x) + barrier + friction.energy(x);
    }

    /** The elastic gradient only, unscaled (for IPC's stiffness balance). */
    void addElasticGradient(double[] x, double[] g) {
        for (Energy term : world.elasticEnergies()) {
            term.addGradient(x, g);
        }
    }

    @Override
    public void addGradient(double[] x, double[] g) {
        double[] ge = new double[g.length];
        addElasticGradient(x, ge);
        for (int i = 0; i < xTilde.length / 3; i++) {
            double m = world.dirichlet[i] ? 0 : world.mass[i];
            for (int c = 0; c < 3; c++) {
                int k = 3 * i + c;
                g[k] += h * h * ge[k] + m * (x[k] - xTilde[k]);
            }
        }
        contacts.addGradient(x, kappa, g);
        friction.addGradient(x, g);
    }

    @Override
    public void addHessian(double[] x, HessianSink sink, boolean project) {
        HessianSink unit = sink instanceof ScaledSink ss ? ss.withScale(1) : sink;
        double[] block = new double[9];
        int[] one = new int[1];
        for (int i = 0; i < xTilde.length / 3; i++) {
            if (world.dirichlet[i]) {
                continue;
            }
            block[0] = world.mass[i];
            block[4] = world.mass[i];
            block[8] = world.mass[i];
            one[0] = i;
            unit.add(one, 1, block);
        }
        HessianSink scaled = (nodes, k, hh) -> {
            double[] s = new double[9 * k * k];
            for (int j = 0; j < s.length; j++) {
                s[j] = h * h * hh[j];
            }
            sink.add(nodes, k, s);
        };
        for (Energy term : world.elasticEnergies()) {
            term.addHessian(x, sink instanceof ScaledSink ss ? ss.withScale(h * h) : scaled, project);
        }
        contacts.addHessian(x, kappa, sink instanceof ScaledSink ss ? ss.withScale(1) : sink, project);
        friction.addHessian(x, sink instanceof ScaledSink ss ? ss.withScale(1) : sink);
    }

    /** A sink that can take a scale factor itself (so no scaled copies are made). */
    interface ScaledSink extends HessianSink {
        HessianSink withScale(double scale);
    }
}
