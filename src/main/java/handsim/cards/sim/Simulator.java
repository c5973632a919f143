package handsim.cards.sim;

import handsim.cards.contact.Barrier;
import handsim.cards.contact.ContactSet;
import handsim.cards.contact.Friction;
import handsim.cards.linalg.SparseSpdSystem;
import java.util.Arrays;

/**
 * Implicit Euler for a card scene, one {@link IncrementalPotential} minimised per step by
 * projected Newton (IPC, Li et al. 2020, Alg. 1): per-element Hessians projected to
 * semi-definite, the sparse system solved by LDLᵀ, and a backtracking line search that starts at
 * the largest step additive CCD allows and halves until E decreases, so every iterate is
 * intersection-free. Bone nodes sit at their targets for the step's end and are not unknowns.
 * Newton stops when the largest node update over h falls below the tolerance (m/s).
 *
 * <p>κ starts at IPC's mass-scaled minimum (or the gradient balance if contacts exist) and
 * doubles, up to 100 times that minimum, while the smallest gap keeps shrinking below ε_d (the
 * IPC Toolkit's adaptive stiffness). Friction is lagged at the start of each step.
 */
public final class Simulator {

    private final SoftWorld world;
    private final SolverSettings settings;
    private final BoneMotion bones;
    private final ContactSet contacts;
    private final Friction friction;
    private final IncrementalPotential potential;
    private final SparseSpdSystem system;
    private final int n;

    private final double[] xt;
    private final double[] x;
    private final double[] trial;
    private final double[] grad;
    private final double[] rhs;
    private final double[] step;
    private final double[] work;
    private final double[] translation = new double[3];
    private final StepStats total = new StepStats();
    private long[] pattern = new long[0];
    private java.util.function.DoubleUnaryOperator gravityScale = t -> 1;
    private long[] couplingKeys = new long[64];
    private int couplingCount;

    public Simulator(SoftWorld world, SolverSettings settings, BoneMotion bones) {
        this.world = world;
        this.settings = settings;
        this.bones = bones;
        this.contacts = new ContactSet(world.collision, settings.dhat(), settings.hashCell());
        this.friction = new Friction(settings.frictionEpsV());
        this.potential = new IncrementalPotential(world, contacts, friction, settings.timeStep(), settings.parallelAssembly());
        this.system = new SparseSpdSystem(world.freeCount);
        this.n = 3 * world.nodeCount();
        xt = new double[n];
        x = new double[n];
        trial = new double[n];
        grad = new double[n];
        rhs = new double[3 * world.freeCount];
        step = new double[n];
        work = new double[3 * world.freeCount];
    }

    /**
     * Scales gravity by a function of time (a warm-up can ramp it on while bones take hold);
     * gravity is full by default.
     */
    public Simulator withGravityScale(java.util.function.DoubleUnaryOperator scale) {
        this.gravityScale = scale;
        return this;
    }

    /** Totals over every step this simulator took. */
    public StepStats stats() {
        return total;
    }

    public SoftWorld world() {
        return world;
    }

    /** Number of active contacts after the last step. */
    public int contactCount() {
        return contacts.size();
    }

    /** Advances {@code state} by one time step. */
    public StepStats step(SimState state) {
        StepStats st = new StepStats();
        double h = settings.timeStep();
        System.arraycopy(state.x, 0, xt, 0, n);
        long t0 = System.nanoTime();
        contacts.build(xt);
        st.contactNanos += System.nanoTime() - t0;
        double[] g = settings.gravity();
        double gs = gravityScale.applyAsDouble(state.time + h);
        potential.prepare(xt, state.v, new double[] {gs * g[0], gs * g[1], gs * g[2]}, state.kappa);
        if (state.kappa == 0) {
            initialiseStiffness(state);
            potential.setKappa(state.kappa);
        }
        friction.lag(contacts, xt, state.kappa, h);
        // bones jump to their targets at the step's end; no bone node is on a contact surface,
        // so the contact set built at x_t stays valid
        System.arraycopy(xt, 0, x, 0, n);
        placeBones(state.time + h, x);
        long e0 = System.nanoTime();
        double energy = potential.value(x);
        st.assemblyNanos += System.nanoTime() - e0;
        boolean converged = false;
        for (int it = 0; it < settings.maxNewtonIterations(); it++) {
            st.newtonIterations++;
            long a0 = System.nanoTime();
            assemble();
            long a1 = System.nanoTime();
            st.assemblyNanos += a1 - a0;
            boolean factored = system.factor();
            for (double shift = 1e-10; !factored && shift < 1; shift *= 100) {
                factored = system.refactorWithShift(shift);
                st.shiftedFactorisations++;
            }
            if (!factored) {
                throw new IllegalStateException("Newton system not positive definite at step " + state.steps);
            }
            system.solve(rhs, work);
            long a2 = System.nanoTime();
            st.solveNanos += a2 - a1;
            double largest = scatterStep();
            if (largest / h < settings.newtonTolerance()) {
                converged = true;
                break;
            }
            long c0 = System.nanoTime();
            double alpha = Math.min(1, contacts.largestSafeStep(x, step, settings.ccdRescaling()));
            st.contactNanos += System.nanoTime() - c0;
            double e = Double.NaN;
            while (alpha > 1e-12) {
                for (int i = 0; i < n; i++) {
                    trial[i] = x[i] + alpha * step[i];
                }
                e = evaluate(trial, st);
                if (e <= energy) {
                    break;
                }
                alpha *= 0.5;
                st.lineSearchHalvings++;
            }
            if (!(e <= energy)) {
                // no decrease along the Newton direction: keep the current iterate
                contacts.build(x);
                break;
            }
            System.arraycopy(trial, 0, x, 0, n);
            energy = e;
            updateStiffness(state);
        }
        if (!converged) {
            st.unconvergedSteps++;
        }
        for (int i = 0; i < n; i++) {
            state.v[i] = (x[i] - xt[i]) / h;
        }
        System.arraycopy(x, 0, state.x, 0, n);
        state.time += h;
        state.steps++;
        st.steps = 1;
        st.maxContacts = contacts.size();
        st.minGap = contacts.minGap(x);
        st.patternBuilds = system.patternBuilds() - total.patternBuilds;
        total.add(st);
        return st;
    }

    /** E at p with the contacts rebuilt there. */
    private double evaluate(double[] p, StepStats st) {
        long c0 = System.nanoTime();
        contacts.build(p);
        long c1 = System.nanoTime();
        double e = potential.value(p);
        st.contactNanos += c1 - c0;
        st.assemblyNanos += System.nanoTime() - c1;
        return e;
    }

    /** The solved update into {@code step} (all nodes, zero on bones); returns its largest entry. */
    private double scatterStep() {
        Arrays.fill(step, 0);
        double largest = 0;
        for (int i = 0; i < n / 3; i++) {
            int f = world.freeIndex[i];
            if (f < 0) {
                continue;
            }
            for (int c = 0; c < 3; c++) {
                step[3 * i + c] = rhs[3 * f + c];
                largest = Math.max(largest, Math.abs(rhs[3 * f + c]));
            }
        }
        return largest;
    }

    /** Writes each fingertip's bone targets at time t into positions {@code pos}. */
    public void placeBones(double t, double[] pos) {
        for (int f = 0; f < world.boneNodes.length; f++) {
            bones.translation(f, t, translation);
            for (int node : world.boneNodes[f]) {
                for (int c = 0; c < 3; c++) {
                    pos[3 * node + c] = world.rest[3 * node + c] + translation[c];
                }
            }
        }
    }

    /** −∇E into rhs (free nodes) and the projected Hessian into the system. */
    private void assemble() {
        updatePattern();
        potential.assemble(x, grad, system, true);
        for (int i = 0; i < n / 3; i++) {
            int f = world.freeIndex[i];
            if (f >= 0) {
                for (int c = 0; c < 3; c++) {
                    rhs[3 * f + c] = -grad[3 * i + c];
                }
            }
        }
    }

    /** Elastic couplings plus those of the current contacts and lagged friction. */
    private void updatePattern() {
        couplingCount = 0;
        contacts.couplings(this::couple);
        friction.couplings(this::couple);
        long[] keys = Arrays.copyOf(couplingKeys, couplingCount);
        Arrays.sort(keys);
        long[] el = world.elasticPairs;
        long[] merged = new long[el.length + keys.length];
        int i = 0;
        int j = 0;
        int m = 0;
        while (i < el.length || j < keys.length) {
            long next = j >= keys.length || (i < el.length && el[i] <= keys[j]) ? el[i++] : keys[j++];
            if (m == 0 || merged[m - 1] != next) {
                merged[m++] = next;
            }
        }
        merged = Arrays.copyOf(merged, m);
        if (!Arrays.equals(merged, pattern)) {
            pattern = merged;
            system.setPattern(pattern);
        }
    }

    private void couple(int a, int b) {
        int fa = world.freeIndex[a];
        int fb = world.freeIndex[b];
        if (fa < 0 || fb < 0 || fa == fb) {
            return;
        }
        if (couplingCount == couplingKeys.length) {
            couplingKeys = Arrays.copyOf(couplingKeys, 2 * couplingCount);
        }
        couplingKeys[couplingCount++] = SparseSpdSystem.pairKey(fa, fb);
    }

    /** IPC's initial κ: the mass-scaled minimum, or the gradient balance with existing contacts. */
    private void initialiseStiffness(SimState state) {
        double xi = world.collision.maxOffsetForStiffness();
        double dhat = settings.dhat();
        double d0 = 1e-8 * world.bboxDiagonal + xi;
        d0 *= d0;
        double sh = 2 * xi * dhat + dhat * dhat;
        double massSum = 0;
        for (double m : world.mass) {
            massSum += m;
        }
        double avgMass = massSum / world.mass.length;
        double kappaMin = settings.kappaScale() * avgMass / (4 * d0 * Barrier.curvature(d0 - xi * xi, sh));
        state.kappaMax = 100 * kappaMin;
        double kappa = kappaMin;
        if (contacts.size() > 0) {
            double[] gb = new double[n];
            contacts.addGradient(xt, 1.0, gb);
            double[] ge = new double[n];
            potential.setKappa(0);
            potential.gradient(xt, ge);
            double num = 0;
            double den = 0;
            for (int i = 0; i < n / 3; i++) {
                if (!world.dirichlet[i]) {
                    for (int c = 0; c < 3; c++) {
                        num -= gb[3 * i + c] * ge[3 * i + c];
                        den += gb[3 * i + c] * gb[3 * i + c];
                    }
                }
            }
            if (den > 0) {
                kappa = Math.max(kappaMin, Math.min(state.kappaMax, num / den));
            }
        }
        state.kappa = kappa;
    }

    /** Doubles κ while the smallest gap d − ξ keeps shrinking below ε_d = 1e-9 (bbox diagonal + ξ). */
    private void updateStiffness(SimState state) {
        double eps = 1e-9 * (world.bboxDiagonal + world.collision.maxOffsetForStiffness());
        double min = contacts.minGap(x);
        if (state.previousMinGap2 < eps && min < eps && min < state.previousMinGap2) {
            state.kappa = Math.min(state.kappaMax, 2 * state.kappa);
            potential.setKappa(state.kappa);
        }
        state.previousMinGap2 = min;
    }
}
