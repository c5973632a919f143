package handsim.cards.sleight;

import handsim.cards.mesh.ShellMesh;
import handsim.cards.mesh.TetMesh;
import handsim.cards.sim.BoneMotion;
import handsim.cards.sim.CardsConfig.Materials;
import handsim.cards.sim.SimState;
import handsim.cards.sim.SoftBody;
import handsim.cards.sim.SoftWorld;
import handsim.cards.sim.SoftWorld.Placement;
import handsim.cards.sim.SolverSettings;

/**
 * The Double Lift scene (thesis 4.2.5, Fig. 4.10): a stack of aligned cards lying flat on a static
 * table (the ground plane z = 0; card long side along x, short side along y), "card1" on top
 * down to "cardN" on the table, stacked at the card thickness plus the configured gap fraction
 * (thesis 4.2.2: 5 %) with that gap to the table too. Two fingertips face the stack's two short
 * ends, one on each side (finger 0 at −x, finger 1 at +x), centred on the short side, each
 * ellipsoid's long axis along the end (y), its pad towards the stack, its skin the configured
 * gap off the cards' ends, its centre hStart above the top of the stack.
 *
 * <p>Two worlds share the cards' nodes, first and in that order: {@link #stackWorld()}, the cards
 * alone and all free, which the warm-up brings to rest; and {@link #world()}, where the top
 * {@code freeCards} move, the deck below lies still where the warm-up left it (its energy is
 * constant, it still carries what lies on it), and the fingertips follow.
 *
 * <p>Bone motion: a pinch of vp (t1 − t0) along ±x towards the stack in [t0, t1], then a lift of
 * vs (t3 − t2) up in [t2, t3], both eased ({@link BoneWindows}), from the start height hStart.
 */
public final class LiftScene {

    /** fingertip frame (x along the finger, y across, z towards the pad) to world, row-major: pad towards +x / −x, proper rotations */
    private static final double[][] FINGER_ROTATION = {{0, 0, 1, 1, 0, 0, 0, 1, 0}, {0, 0, -1, 1, 0, 0, 0, -1, 0}};

    private final LiftConfig config;
    private final SoftWorld stackWorld;
    private final SoftWorld world;
    private final int cardNodes;
    private final double topOfStack;

    public LiftScene(LiftConfig config, Materials materials, SolverSettings settings) {
        this.config = config;
        CardSpec spec = config.card();
        ShellMesh card = spec.mesh();
        double t = materials.card().thickness();
        double gap = t * spec.gapFraction();
        double spacing = t + gap;
        int n = config.count();
        SoftWorld.Builder stack = new SoftWorld.Builder().friction(settings.friction()).ground(0);
        SoftWorld.Builder trial = new SoftWorld.Builder().friction(settings.friction()).ground(0);
        for (int k = 1; k <= n; k++) {
            Placement at = Placement.at(0, 0, t / 2 + gap + (n - k) * spacing);
            stack.card(cardName(k), card, materials.card(), at);
            trial.card(cardName(k), card, materials.card(), at);
            if (k > config.freeCards()) {
                trial.fix(cardName(k));
            }
        }
        topOfStack = t / 2 + gap + (n - 1) * spacing + t / 2;
        TetMesh tip = config.fingertip().mesh();
        double x = spec.length() / 2 + t / 2 + config.initialGap() + config.fingertip().semiAxes()[2];
        trial.fingertip("finger0", tip, materials.fingertip(), new Placement(FINGER_ROTATION[0], new double[] {-x, 0, topOfStack}));
        trial.fingertip("finger1", tip, materials.fingertip(), new Placement(FINGER_ROTATION[1], new double[] {x, 0, topOfStack}));
        stackWorld = stack.build();
        world = trial.build();
        cardNodes = n * card.vertexCount();
    }

    /** Card k's body name, 1 on top. */
    public static String cardName(int k) {
        return "card" + k;
    }

    public LiftConfig config() {
        return config;
    }

    /** The cards alone, every one free, on the table: the world the warm-up runs. */
    public SoftWorld stackWorld() {
        return stackWorld;
    }

    /** The trial's world: the top cards free, the deck below still, the two fingertips. */
    public SoftWorld world() {
        return world;
    }

    /** Height of the rest geometry's top card's upper face (m); hStart is measured from it. */
    public double topOfStack() {
        return topOfStack;
    }

    /**
     * The state a trial starts from: the rested stack's cards (positions, velocities, barrier
     * stiffness), the fingertips at rest, raised by hStart; time and step count zero.
     */
    public SimState startState(SimState restedStack, double hStart) {
        if (restedStack.nodeCount() * 3 != 3 * cardNodes) {
            throw new IllegalArgumentException("a rested stack of " + restedStack.nodeCount() + " nodes, the scene's cards have " + cardNodes);
        }
        double[] x = world.restPositions();
        double[] v = new double[x.length];
        System.arraycopy(restedStack.x, 0, x, 0, 3 * cardNodes);
        System.arraycopy(restedStack.v, 0, v, 0, 3 * cardNodes);
        for (int i = 3 * cardNodes + 2; i < x.length; i += 3) {
            x[i] += hStart;
        }
        SimState s = new SimState(x, v);
        s.kappa = restedStack.kappa;
        s.kappaMax = restedStack.kappaMax;
        s.previousMinGap2 = restedStack.previousMinGap2;
        return s;
    }

    /** The bones' motion in a trial with {@code p}: raised by hStart, pinched in along ±x, lifted along z. */
    public BoneMotion motion(LiftParams p) {
        BoneWindows w = p.windows();
        return (finger, time, out) -> {
            double inwards = finger == 0 ? 1 : -1;
            out[0] = inwards * w.pinch(time);
            out[1] = 0;
            out[2] = p.hStart() + w.second(time);
        };
    }

    /** Mean position of card k's nodes (m). */
    public double[] centroid(SimState s, int k) {
        SoftBody b = world.body(cardName(k));
        double[] c = new double[3];
        for (int i = b.firstNode(); i < b.firstNode() + b.nodeCount(); i++) {
            for (int d = 0; d < 3; d++) {
                c[d] += s.x[3 * i + d] / b.nodeCount();
            }
        }
        return c;
    }

    /** How far card k's centroid rose from {@code start} to {@code end} (m; negative: it sank). */
    public double rise(SimState start, SimState end, int k) {
        return centroid(end, k)[2] - centroid(start, k)[2];
    }

    /** How far card k's centroid moved from {@code start} to {@code end} (m). */
    public double displacement(SimState start, SimState end, int k) {
        double[] a = centroid(start, k);
        double[] b = centroid(end, k);
        return Math.sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]));
    }
}
