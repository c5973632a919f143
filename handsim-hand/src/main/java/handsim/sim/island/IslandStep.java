package handsim.sim.island;

/**
 * One time step of h seconds for bodies joined by an {@link Articulation} and by the step's
 * {@link ContactPoints}, in the order of ODE's quickStep: gravity, world inverse inertias and the
 * gyroscopic torque ({@link RigidBodies#prepare}); the islands and their joints' order
 * ({@link IslandOrder}); the constraint rows ({@link RowAssembly}); per island the projected SOR
 * solve ({@link ProjectedSor}); the constraint impulses, the applied forces and the integration
 * of the poses with air damping ({@link RigidBodies#integrate}). The contacts are cleared after
 * the step.
 *
 * <p>A world owns its step: the random row order is drawn from the step's own generator
 * ({@link #setSeed}), so steps of different worlds on different threads never meet.
 */
public final class IslandStep {

    /**
     * What a step needs besides the bodies and joints.
     *
     * @param timeStep h, s
     * @param gravity m/s^2 (x, y, z)
     * @param iterations SOR sweeps per step
     * @param sor the over-relaxation factor w
     * @param erp the joints' error reduction per step (ODE's world ERP)
     * @param cfm the joints' constraint force mixing (ODE's world CFM)
     * @param linearDamping each step scales every linear velocity by 1 - this
     * @param angularDamping each step scales every angular velocity by 1 - this
     */
    public record Settings(double timeStep, double[] gravity, int iterations, double sor, double erp, double cfm,
            double linearDamping, double angularDamping) {
    }

    private final Settings settings;
    private final RigidBodies bodies;
    private final Articulation articulation;
    private final ContactPoints contacts = new ContactPoints();
    private final IslandOrder islands;
    private final RowAssembly assembly;
    private final ConstraintRows rows;
    private final ProjectedSor solver;
    private final ShuffleRandom random = new ShuffleRandom();
    /** Island i holds rows [rowStart[i], rowStart[i + 1]). */
    private int[] rowStart;
    /** The rows of the island order's n-th joint are [jointRowStart[n], jointRowStart[n + 1]). */
    private int[] jointRowStart = new int[64];

    /**
     * @param listOrder the bodies in the engine's body list order, the most recently created
     *     first: the order in which islands are searched
     */
    public IslandStep(Settings settings, RigidBodies bodies, Articulation articulation, int[] listOrder) {
        this.settings = settings;
        this.bodies = bodies;
        this.articulation = articulation;
        islands = new IslandOrder(articulation, bodies.count, listOrder);
        assembly = new RowAssembly(settings.erp(), settings.cfm());
        int capacity = 0;
        for (int j = 0; j < articulation.count; j++) {
            capacity += articulation.maxRows(j);
        }
        rows = new ConstraintRows(capacity + 3 * 32);
        solver = new ProjectedSor(bodies.count);
        rowStart = new int[bodies.count + 1];
    }

    public RigidBodies bodies() {
        return bodies;
    }

    public ContactPoints contacts() {
        return contacts;
    }

    /** Seeds the generator of the random row order. */
    public void setSeed(long seed) {
        random.setSeed(seed);
    }

    /** The generator's state, which {@link #setSeed} restores. */
    public long seed() {
        return random.seed();
    }

    /**
     * Advances the bodies by one step.
     *
     * @param angles the articulation's DOF angles at the start of the step (rad), for its stops
     * @param dofAxes the DOFs' world axes (3 each), for the Euler angles' stops
     */
    public void step(double[] angles, double[] dofAxes) {
        double h = settings.timeStep();
        double[] g = settings.gravity();
        bodies.prepare(h, g[0], g[1], g[2]);
        assemble(angles, dofAxes);
        solver.prepare(bodies, h);
        for (int i = 0; i < islands.islandCount; i++) {
            solver.solve(rows, rowStart[i], rowStart[i + 1], bodies, h, settings.iterations(), settings.sor(), random);
        }
        for (int i = 0; i < bodies.count; i++) {
            if (bodies.dynamic(i)) {
                bodies.addConstraintVelocity(i, h, solver.fc);
            }
        }
        bodies.integrate(h, settings.linearDamping(), settings.angularDamping());
        contacts.clear();
    }

    /** The islands and every row, island after island, in ODE's order. */
    void assemble(double[] angles, double[] dofAxes) {
        double fps = 1 / settings.timeStep();
        islands.build(articulation, contacts, bodies.active);
        rows.clear();
        if (jointRowStart.length <= islands.jointCount) {
            jointRowStart = new int[2 * islands.jointCount + 1];
        }
        for (int i = 0; i < islands.islandCount; i++) {
            rowStart[i] = rows.count;
            for (int n = islands.islandStart[i]; n < islands.islandStart[i + 1]; n++) {
                jointRowStart[n] = rows.count;
                int joint = islands.joints[n];
                if (joint >= 0) {
                    assembly.joint(articulation, joint, bodies, rows, fps, angles, dofAxes);
                } else {
                    assembly.contact(contacts, -joint - 1, bodies, rows, fps);
                }
            }
        }
        rowStart[islands.islandCount] = rows.count;
        jointRowStart[islands.jointCount] = rows.count;
    }

    /**
     * One assembled row, as ODE's joints state it before the step makes it a rate (rhs and cfm
     * per step of h).
     *
     * @param joint the articulation joint it belongs to, or {@code -(k + 1)} for contact k
     * @param j1 body 1's linear and angular Jacobian (6)
     * @param j2 body 2's (6; zero without a body 2)
     * @param findex the row of its joint whose impulse bounds it (0 the joint's first), -1 for none
     * @param zeros the indices (of 6) at which the assembly declares J1 and J2 zero, which the
     *     solver's sweep then leaves out
     */
    public record AssembledRow(int joint, double[] j1, double[] j2, double rhs, double cfm, double lo, double hi, int findex, int[] zeros) {
    }

    /**
     * The rows of the current bodies, joints and contacts, in the order the step assembles them
     * (for inspection and tests; allocates).
     */
    public java.util.List<AssembledRow> assembledRows(double[] angles, double[] dofAxes) {
        assemble(angles, dofAxes);
        java.util.List<AssembledRow> out = new java.util.ArrayList<>();
        double[] d = rows.data;
        for (int n = 0; n < islands.jointCount; n++) {
            for (int r = jointRowStart[n]; r < jointRowStart[n + 1]; r++) {
                int o = ConstraintRows.STRIDE * r;
                int f = rows.findex[r];
                out.add(new AssembledRow(islands.joints[n], java.util.Arrays.copyOfRange(d, o + ConstraintRows.J1, o + ConstraintRows.J1 + 6),
                        java.util.Arrays.copyOfRange(d, o + ConstraintRows.J2, o + ConstraintRows.J2 + 6), d[o + ConstraintRows.RHS],
                        d[o + ConstraintRows.CFM], d[o + ConstraintRows.LO], d[o + ConstraintRows.HI], f < 0 ? -1 : f - jointRowStart[n],
                        ConstraintRows.zeros(rows.shape[r])));
            }
        }
        return out;
    }
}
