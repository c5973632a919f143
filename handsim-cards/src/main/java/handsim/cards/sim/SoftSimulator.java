package handsim.cards.sim;

import handsim.cards.contact.Barrier;
import handsim.cards.contact.BudgetExceeded;
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
public final class SoftSimulator {

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
    private final double[] translation = new double[3];
    private final double[] rotation = new double[3];
    private final double[] turn = new double[9];
    /** Each fingertip's bone centre at rest (the centroid of its bone nodes), the pivot of its turns. */
    private final double[][] boneCentres;
    private final StepStats total = new StepStats();
    private long[] pattern = new long[0];
    private java.util.function.DoubleUnaryOperator gravityScale = t -> 1;
    private long[] couplingKeys = new long[64];
    private int couplingCount;
    /** Budget of this simulation: Newton iterations in all, and the wall-time deadline (System.nanoTime). */
    private long maxNewtonIterations = Long.MAX_VALUE;
    private double maxWallSeconds = Double.POSITIVE_INFINITY;
    private long wallStart;

    public SoftSimulator(SoftWorld world, SolverSettings settings, BoneMotion bones) {
        this.world = world;
        this.settings = settings;
        this.bones = bones;
        this.contacts = new ContactSet(world.collision, settings.dhat(), settings.hashCell());
        contacts.useGaussNewton(settings.gaussNewtonContacts());
        this.friction = new Friction(settings.frictionEpsV());
        this.potential = new IncrementalPotential(world, contacts, friction, settings.timeStep(), settings.parallel());
        this.system = new SparseSpdSystem(world.freeCount, settings.factorisation(), settings.parallel());
        this.n = 3 * world.nodeCount();
        xt = new double[n];
        x = new double[n];
        trial = new double[n];
        grad = new double[n];
        rhs = new double[3 * world.freeCount];
        step = new double[n];
        boneCentres = new double[world.boneNodes.length][3];
        for (int f = 0; f < boneCentres.length; f++) {
            for (int node : world.boneNodes[f]) {
                for (int c = 0; c < 3; c++) {
                    boneCentres[f][c] += world.rest[3 * node + c] / world.boneNodes[f].length;
                }
            }
        }
    }

    /**
     * Scales gravity by a function of time (a warm-up can ramp it on while bones take hold);
     * gravity is full by default.
     */
    public SoftSimulator withGravityScale(java.util.function.DoubleUnaryOperator scale) {
        this.gravityScale = scale;
        return this;
    }

    /**
     * Limits this simulation, of {@code simulatedSeconds} in all, to {@code budget}: past its
     * memory for contacts, its Newton iterations or its wall time (counted from now) a step
     * throws {@link BudgetExceeded}.
     */
    public SoftSimulator withBudget(TrialBudget budget, double simulatedSeconds) {
        contacts.limit(budget.maxHashEntries(), budget.maxContactPairs());
        this.maxNewtonIterations = budget.newtonIterationsFor(simulatedSeconds);
        this.maxWallSeconds = budget.maxWallSeconds();
        this.wallStart = System.nanoTime();
        return this;
    }

    /** Throws {@link BudgetExceeded} when this simulation has used up its Newton iterations or its wall time. */
    private void checkBudget(SimState state, StepStats st) {
        if (total.newtonIterations + st.newtonIterations > maxNewtonIterations) {
            throw new BudgetExceeded("more than " + maxNewtonIterations + " Newton iterations by step " + (state.steps + 1)
                    + " (configs/cards/budget.json maxNewtonIterationsPerSecond): the solver struggles with this trial");
        }
        double wall = (System.nanoTime() - wallStart) * 1e-9;
        if (wall > maxWallSeconds) {
            throw new BudgetExceeded(String.format(java.util.Locale.ROOT, "%.0f s of wall time by step %d (configs/cards/budget.json "
                    + "maxWallSeconds %s)", wall, state.steps + 1, handsim.config.Json.show(maxWallSeconds)));
        }
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
        // each step starts from its state alone (so a checkpoint resumes bit for bit): the exact
        // pattern, and no factorisation kept from the step before
        system.forgetFactorisation();
        for (int it = 0; it < settings.maxNewtonIterations(); it++) {
            st.newtonIterations++;
            checkBudget(state, st);
            long a0 = System.nanoTime();
            assemble(it == 0);
            long a1 = System.nanoTime();
            st.assemblyNanos += a1 - a0;
            if (!system.solve(rhs, settings.cgTolerance(), settings.cgMaxIterations())) {
                throw new IllegalStateException("Newton system not positive definite at step " + state.steps);
            }
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
                contacts.buildAlongSweep(x);
                break;
            }
            System.arraycopy(trial, 0, x, 0, n);
            energy = e;
            if (updateStiffness(state)) {
                // E changed with κ: the next line search compares against E at x with the new κ
                energy = potential.value(x);
            }
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
        st.factorisations = system.factorisations() - total.factorisations;
        st.cgIterations = system.cgIterations() - total.cgIterations;
        st.shiftedFactorisations = system.shiftedFactorisations() - total.shiftedFactorisations;
        total.add(st);
        return st;
    }

    /** E at p, a point of the last CCD sweep, with the contacts rebuilt there. */
    private double evaluate(double[] p, StepStats st) {
        long c0 = System.nanoTime();
        contacts.buildAlongSweep(p);
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
            bones.rotation(f, t, rotation);
            if (rotation[0] == 0 && rotation[1] == 0 && rotation[2] == 0) {
                // a pure translation, added to the rest positions as they are (no round trip through the centre)
                for (int node : world.boneNodes[f]) {
                    for (int c = 0; c < 3; c++) {
                        pos[3 * node + c] = world.rest[3 * node + c] + translation[c];
                    }
                }
                continue;
            }
            rotationMatrix(rotation, turn);
            double[] centre = boneCentres[f];
            for (int node : world.boneNodes[f]) {
                double rx = world.rest[3 * node] - centre[0];
                double ry = world.rest[3 * node + 1] - centre[1];
                double rz = world.rest[3 * node + 2] - centre[2];
                for (int c = 0; c < 3; c++) {
                    pos[3 * node + c] = centre[c] + turn[3 * c] * rx + turn[3 * c + 1] * ry + turn[3 * c + 2] * rz + translation[c];
                }
            }
        }
    }

    /** Rodrigues' formula: the row-major rotation matrix of rotation vector {@code v} into {@code r}. */
    static void rotationMatrix(double[] v, double[] r) {
        double angle = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        double kx = v[0] / angle;
        double ky = v[1] / angle;
        double kz = v[2] / angle;
        double c = Math.cos(angle);
        double s = Math.sin(angle);
        double u = 1 - c;
        r[0] = c + kx * kx * u;
        r[1] = kx * ky * u - kz * s;
        r[2] = kx * kz * u + ky * s;
        r[3] = ky * kx * u + kz * s;
        r[4] = c + ky * ky * u;
        r[5] = ky * kz * u - kx * s;
        r[6] = kz * kx * u - ky * s;
        r[7] = kz * ky * u + kx * s;
        r[8] = c + kz * kz * u;
    }

    /** −∇E into rhs (free nodes) and the projected Hessian into the system; the exact pattern at a step's start. */
    private void assemble(boolean stepStart) {
        updatePattern(stepStart);
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

    /**
     * The Newton system's pattern: the elastic couplings plus those of the current contacts and
     * lagged friction. Contacts come and go from one Newton iteration to the next, and a new
     * pattern costs a new ordering and symbolic factorisation, so within a step the pattern is
     * kept while it holds every coupling needed and at most {@link #SPARE_PAIRS} (or as many as
     * the contacts need, if more) pairs not needed any more, which carry zeros; otherwise it becomes
     * the needed couplings plus the kept ones within that allowance, or just the needed ones. At
     * a step's start ({@code exact}) it is just the needed couplings.
     */
    private void updatePattern(boolean exact) {
        couplingCount = 0;
        contacts.couplings(this::couple);
        friction.couplings(this::couple);
        long[] keys = Arrays.copyOf(couplingKeys, couplingCount);
        Arrays.sort(keys);
        long[] needed = union(world.elasticPairs, keys);
        int allowance = exact ? 0 : Math.max(SPARE_PAIRS, needed.length - world.elasticPairs.length);
        if (pattern.length - needed.length <= allowance && union(pattern, needed).length == pattern.length) {
            return;
        }
        long[] grown = union(pattern, needed);
        pattern = grown.length - needed.length <= allowance ? grown : needed;
        system.setPattern(pattern);
    }

    /** Pairs kept in the pattern beyond those needed, at least. */
    private static final int SPARE_PAIRS = 256;

    /** The sorted union of two sorted arrays of distinct keys. */
    private static long[] union(long[] a, long[] b) {
        long[] merged = new long[a.length + b.length];
        int i = 0;
        int j = 0;
        int m = 0;
        while (i < a.length || j < b.length) {
            long next = j >= b.length || (i < a.length && a[i] <= b[j]) ? a[i++] : b[j++];
            if (m == 0 || merged[m - 1] != next) {
                merged[m++] = next;
            }
        }
        return Arrays.copyOf(merged, m);
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

    /** Doubles κ while the smallest gap d − ξ keeps shrinking below ε_d = 1e-9 (bbox diagonal + ξ); whether it did. */
    private boolean updateStiffness(SimState state) {
        double eps = 1e-9 * (world.bboxDiagonal + world.collision.maxOffsetForStiffness());
        double min = contacts.minGap(x);
        boolean grows = state.previousMinGap2 < eps && min < eps && min < state.previousMinGap2 && state.kappa < state.kappaMax;
        if (grows) {
            state.kappa = Math.min(state.kappaMax, 2 * state.kappa);
            potential.setKappa(state.kappa);
        }
        state.previousMinGap2 = min;
        return grows;
    }
}
