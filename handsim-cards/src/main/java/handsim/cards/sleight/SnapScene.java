package handsim.cards.sleight;

import handsim.cards.mesh.TetMesh;
import handsim.cards.mesh.ShellMesh;
import handsim.cards.sim.BoneMotion;
import handsim.cards.sim.CardsConfig.Materials;
import handsim.cards.sim.SimState;
import handsim.cards.sim.SoftWorld;
import handsim.cards.sim.SoftWorld.Placement;
import handsim.cards.sim.SolverSettings;
import java.util.ArrayList;
import java.util.List;

/**
 * The Card Snapping scene. The two cards hang in the world xz-plane (long side vertical along z,
 * normal along y), stacked at thickness (1 + gapFraction), gravity along −z. Fingertip 0 (the
 * thumb) touches card 0 from −y, fingertip 1 touches card 1 from +y, both centred on the cards'
 * short side, {@code pinchBelowTop} below their top edge, each ellipsoid's long axis along the
 * card's long side and its shortest along the normal.
 *
 * <p>Bone motion: in the first half of the hold (the warm-up) both bones close in by {@code depth}
 * along ±y, then gravity ramps on over the second half; in the
 * trial they pinch by a further vp (t1 − t0) along ±y in [t0, t1] and slide in opposite
 * directions along x, thumb −x and finger +x, by vs (t3 − t2) in [t2, t3]. Each window follows a
 * half-cosine ease, so its mean speed is the parameter's. With {@code slide: "turn"} the slide
 * window turns the bones instead, about the cards' normal through each bone's centre, the thumb
 * one way and the finger the other, by the angle whose arc at the fingertip's long semi-axis is
 * vs (t3 − t2): the pads stay on the cards and move in their plane, along arcs.
 */
public final class SnapScene {

    /** card local (x long, y short, z normal) to world (z, x, y) */
    private static final double[] ROTATION = {0, 1, 0, 0, 0, 1, 1, 0, 0};

    private final SnapConfig config;
    private final SoftWorld world;
    private final int[][] cardTop;
    private final int[][] cardBottom;
    private final int[][] cardNodes;

    public SnapScene(SnapConfig config, Materials materials, SolverSettings settings) {
        this.config = config;
        CardSpec cardSpec = config.card();
        ShellMesh card = cardSpec.mesh();
        double[] a = config.fingertip().semiAxes();
        TetMesh tip = config.fingertip().mesh();
        double t = materials.card().thickness();
        double spacing = t * (1 + cardSpec.gapFraction());
        double tipY = spacing / 2 + t / 2 + a[2] + config.initialGap();
        double tipZ = cardSpec.length() / 2 - config.pinchBelowTop();
        world = new SoftWorld.Builder()
                .friction(settings.friction())
                .card("card0", card, materials.card(), new Placement(ROTATION, new double[] {0, -spacing / 2, 0}))
                .card("card1", card, materials.card(), new Placement(ROTATION, new double[] {0, spacing / 2, 0}))
                .fingertip("thumb", tip, materials.fingertip(), new Placement(ROTATION, new double[] {0, -tipY, tipZ}))
                .fingertip("finger", tip, materials.fingertip(), new Placement(ROTATION, new double[] {0, tipY, tipZ}))
                .build();
        // the card's short edges: its top and bottom rows of vertices (local x = ±length/2)
        double[] v = card.vertices();
        List<Integer> top = new ArrayList<>();
        List<Integer> bottom = new ArrayList<>();
        for (int i = 0; i < card.vertexCount(); i++) {
            if (Math.abs(v[3 * i] - config.card().length() / 2) < 1e-9) {
                top.add(i);
            } else if (Math.abs(v[3 * i] + config.card().length() / 2) < 1e-9) {
                bottom.add(i);
            }
        }
        cardTop = new int[2][];
        cardNodes = new int[2][];
        cardBottom = new int[2][];
        for (int c = 0; c < 2; c++) {
            int first = world.body("card" + c).firstNode();
            cardTop[c] = top.stream().mapToInt(i -> first + i).toArray();
            cardBottom[c] = bottom.stream().mapToInt(i -> first + i).toArray();
            cardNodes[c] = java.util.stream.IntStream.range(first, first + card.vertexCount()).toArray();
        }
    }

    public SoftWorld world() {
        return world;
    }

    public SnapConfig config() {
        return config;
    }

    /** The bone motion of the hold followed by a trial with {@code p} (trial time starts after the warm-up). */
    public BoneMotion motion(SnapParams p) {
        double w = config.warmup();
        double depth = config.holdDepth();
        BoneWindows windows = p == null ? null : p.windows();
        boolean turn = config.slide() == SnapConfig.Slide.TURN;
        // a turn's arc is measured at the fingertip's long semi-axis, the reach of its pad along the card
        double arcRadius = config.fingertip().semiAxes()[0];
        return new BoneMotion() {
            @Override
            public void translation(int finger, double time, double[] out) {
                double sign = finger == 0 ? 1 : -1;
                double hold = depth * BoneWindows.ease(time, 0, 0.5 * w);
                double tt = time - w;
                double pinch = windows == null ? 0 : windows.pinch(tt);
                double slide = windows == null || turn ? 0 : windows.second(tt);
                out[0] = -sign * slide;
                out[1] = sign * (hold + pinch);
                out[2] = 0;
            }

            @Override
            public void rotation(int finger, double time, double[] out) {
                double sign = finger == 0 ? 1 : -1;
                double arc = windows == null || !turn ? 0 : windows.second(time - w);
                out[0] = 0;
                out[1] = sign * arc / arcRadius;
                out[2] = 0;
            }
        };
    }

    /** Unit long axis of card c (bottom-edge midpoint to top-edge midpoint). */
    public double[] longAxis(SimState state, int c) {
        double[] top = centroid(state.x, cardTop[c]);
        double[] bottom = centroid(state.x, cardBottom[c]);
        double[] a = {top[0] - bottom[0], top[1] - bottom[1], top[2] - bottom[2]};
        double len = Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        return new double[] {a[0] / len, a[1] / len, a[2] / len};
    }

    /** How far each card's centroid lies below where it was in {@code reference} (m); the larger of the two. */
    public double cardDrop(SimState reference, SimState state) {
        double drop = 0;
        for (int c = 0; c < 2; c++) {
            drop = Math.max(drop, centroid(reference.x, cardNodes[c])[2] - centroid(state.x, cardNodes[c])[2]);
        }
        return drop;
    }

    /** α: the angle between the two cards' long axes (degrees). */
    public double angleBetweenCards(SimState state) {
        double[] a = longAxis(state, 0);
        double[] b = longAxis(state, 1);
        double dot = Math.max(-1, Math.min(1, a[0] * b[0] + a[1] * b[1] + a[2] * b[2]));
        return Math.toDegrees(Math.acos(dot));
    }

    private static double[] centroid(double[] x, int[] nodes) {
        double[] c = new double[3];
        for (int n : nodes) {
            for (int d = 0; d < 3; d++) {
                c[d] += x[3 * n + d] / nodes.length;
            }
        }
        return c;
    }
}
