package handsim.cards.sim;

import handsim.cards.contact.ContactSet;
import handsim.cards.contact.Friction;
import handsim.cards.energy.Energy;
import handsim.cards.energy.HessianSink;
import handsim.cards.linalg.SparseSpdSystem;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;

/**
 * The incremental potential of one implicit Euler step (IPC, Li et al. 2020, eq. 3):
 * E(x) = ½ ‖x − x̃‖²_M + h² Ψ(x) + κ Σ b + h² D(x) over all nodes (bone nodes carry no inertia
 * term: they are not unknowns). The contact set is whatever was last built; the simulator
 * rebuilds it at every configuration it evaluates.
 *
 * <p>Assembly always splits every element list and the contact list into the same two halves,
 * each with its own scratch memory, gradient buffers and Hessian accumulator, and adds the halves
 * in a fixed order. The halves run on two threads when {@code parallel} is set, one after the
 * other otherwise: the arithmetic, and so the trajectory, is the same bit for bit either way.
 */
public final class IncrementalPotential {

    private static final int PARTS = 2;

    private final SoftWorld world;
    private final ContactSet contacts;
    private final Friction friction;
    private final double h;
    private final double[] xTilde;
    private final boolean parallel;
    private final Part[] parts = new Part[PARTS];
    private double kappa;

    IncrementalPotential(SoftWorld world, ContactSet contacts, Friction friction, double timeStep, boolean parallel) {
        this.world = world;
        this.contacts = contacts;
        this.friction = friction;
        this.h = timeStep;
        this.parallel = parallel;
        this.xTilde = new double[3 * world.nodeCount()];
        for (int k = 0; k < PARTS; k++) {
            parts[k] = new Part(k);
        }
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

    /** One half of the work, with its own scratch memory. */
    private final class Part {
        final int index;
        final List<Energy> energies;
        final ContactSet.Scratch scratch = new ContactSet.Scratch();
        final double[] elasticGrad;
        final double[] contactGrad;
        SparseSpdSystem.Accumulator hessian;
        double elastic;
        double barrier;

        Part(int index) {
            this.index = index;
            this.energies = world.elasticEnergies().stream().map(Energy::workspaceCopy).toList();
            this.elasticGrad = new double[3 * world.nodeCount()];
            this.contactGrad = new double[3 * world.nodeCount()];
        }

        int from(int count) {
            return count * index / PARTS;
        }

        int to(int count) {
            return count * (index + 1) / PARTS;
        }

        void value(double[] x) {
            elastic = 0;
            for (Energy e : energies) {
                elastic += e.value(x, from(e.elementCount()), to(e.elementCount()));
            }
            int n = contacts.size();
            barrier = contacts.energy(x, kappa, from(n), to(n), scratch);
        }

        void assemble(double[] x, SparseSpdSystem system, boolean project) {
            Arrays.fill(elasticGrad, 0);
            Arrays.fill(contactGrad, 0);
            hessian.clear();
            HessianSink elasticSink = sink(system, h * h);
            for (Energy e : energies) {
                e.addGradientAndHessian(x, from(e.elementCount()), to(e.elementCount()), elasticGrad, elasticSink, project);
            }
            HessianSink unitSink = sink(system, 1);
            int n = contacts.size();
            contacts.addGradient(x, kappa, from(n), to(n), contactGrad, scratch);
            contacts.addHessian(x, kappa, from(n), to(n), unitSink, project, scratch);
            if (index == 0) {
                friction.addGradient(x, contactGrad);
                friction.addHessian(x, unitSink);
            }
        }

        /** Routes element Hessians of all nodes to this part's accumulator (free nodes only). */
        HessianSink sink(SparseSpdSystem system, double scale) {
            return (nodes, k, hh) -> {
                int stride = 3 * k;
                for (int a = 0; a < k; a++) {
                    int fa = world.freeIndex[nodes[a]];
                    if (fa < 0) {
                        continue;
                    }
                    for (int b = a; b < k; b++) {
                        int fb = world.freeIndex[nodes[b]];
                        if (fb >= 0) {
                            hessian.addBlock(fa, fb, hh, 3 * a * stride + 3 * b, stride, scale);
                        }
                    }
                }
            };
        }
    }

    /** Runs {@code work} on both parts, on two threads when parallel. */
    private void forParts(java.util.function.Consumer<Part> work) {
        if (!parallel) {
            for (Part p : parts) {
                work.accept(p);
            }
            return;
        }
        ForkJoinTask<?> second = ForkJoinPool.commonPool().submit(() -> work.accept(parts[1]));
        work.accept(parts[0]);
        second.join();
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

    /** E(x) with the contacts last built; +∞ if a pair touches. */
    public double value(double[] x) {
        forParts(p -> p.value(x));
        double barrier = parts[0].barrier + parts[1].barrier;
        if (barrier == Double.POSITIVE_INFINITY) {
            return barrier;
        }
        return inertia(x) + h * h * (parts[0].elastic + parts[1].elastic) + barrier + friction.energy(x);
    }

    /** ∇E into g (all nodes) and the (projected) Hessian of the free nodes into the system. */
    void assemble(double[] x, double[] g, SparseSpdSystem system, boolean project) {
        for (Part p : parts) {
            if (p.hessian == null) {
                p.hessian = system.accumulator();
            }
        }
        forParts(p -> p.assemble(x, system, project));
        system.sum(parts[0].hessian, parts[1].hessian);
        for (int i = 0; i < xTilde.length / 3; i++) {
            int f = world.freeIndex[i];
            double m = f < 0 ? 0 : world.mass[i];
            if (f >= 0) {
                system.addDiagonal(f, m);
            }
            for (int c = 0; c < 3; c++) {
                int k = 3 * i + c;
                g[k] = h * h * (parts[0].elasticGrad[k] + parts[1].elasticGrad[k])
                        + (parts[0].contactGrad[k] + parts[1].contactGrad[k]) + m * (x[k] - xTilde[k]);
            }
        }
    }

    /** ∇E (all nodes), sequentially, for checks. */
    public void gradient(double[] x, double[] g) {
        double[] ge = new double[g.length];
        for (Energy e : world.elasticEnergies()) {
            e.addGradient(x, ge);
        }
        double[] gc = new double[g.length];
        contacts.addGradient(x, kappa, gc);
        friction.addGradient(x, gc);
        for (int i = 0; i < xTilde.length / 3; i++) {
            double m = world.dirichlet[i] ? 0 : world.mass[i];
            for (int c = 0; c < 3; c++) {
                int k = 3 * i + c;
                g[k] = h * h * ge[k] + gc[k] + m * (x[k] - xTilde[k]);
            }
        }
    }

    /** The Hessian of E element by element, sequentially, for checks. */
    public void hessian(double[] x, HessianSink sink, boolean project) {
        double[] block = new double[9];
        for (int i = 0; i < xTilde.length / 3; i++) {
            if (!world.dirichlet[i]) {
                block[0] = world.mass[i];
                block[4] = world.mass[i];
                block[8] = world.mass[i];
                sink.add(new int[] {i}, 1, block);
            }
        }
        HessianSink scaled = (nodes, k, hh) -> {
            double[] s = new double[9 * k * k];
            for (int j = 0; j < s.length; j++) {
                s[j] = h * h * hh[j];
            }
            sink.add(nodes, k, s);
        };
        for (Energy e : world.elasticEnergies()) {
            e.addHessian(x, scaled, project);
        }
        contacts.addHessian(x, kappa, sink, project);
        friction.addHessian(x, sink);
    }
}
