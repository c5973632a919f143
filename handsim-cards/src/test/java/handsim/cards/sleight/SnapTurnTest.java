package handsim.cards.sleight;

import static org.junit.jupiter.api.Assertions.assertEquals;

import handsim.cards.sim.CardsConfig;
import handsim.cards.sim.SoftBody;
import handsim.cards.sim.SoftSimulator;
import handsim.cards.sim.SoftWorld;
import handsim.config.Json;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * The turning slide of Card Snapping ({@code trial.slide: "turn"}): after the slide window each
 * bone has turned rigidly about the cards' normal (world y) through its own centre, the thumb by
 * +vs (t3 − t2) / a and the finger by the opposite angle, a the fingertip's long semi-axis; the
 * straight slide (thesis 4.2.4) moves the bones along x without turning them.
 */
class SnapTurnTest {

    private static final SnapParams PARAMS = new SnapParams(0, 0.1, 0.003, 0.15, 0.35, 0.01);

    private static SnapScene scene(String slide) {
        Path dir = Path.of("configs/cards");
        Json snap = Json.of("snap.json", Json.withOverrides("snap.json", Json.load(dir.resolve("snap.json")).node(),
                Map.of("fingertip.mesh", "\"coarse\"", "trial.slide", "\"" + slide + "\"")));
        return new SnapScene(SnapConfig.parse(snap, null), CardsConfig.materials(dir.resolve("materials.json"), null),
                CardsConfig.solver(dir.resolve("solver.json")));
    }

    @Test
    void theTurnRotatesEachBoneRigidlyAboutTheCardsNormal() {
        SnapScene scene = scene("turn");
        double a = scene.config().fingertip().semiAxes()[0];
        // the arc of the slide window, 2 mm, at the 12 mm semi-axis: 0.1667 rad each way
        double expected = PARAMS.windows().vs() * (PARAMS.windows().t3() - PARAMS.windows().t2()) / a;
        double end = scene.config().warmup() + 0.4;
        for (int f = 0; f < 2; f++) {
            double[] turned = boneOffsets(scene, f, end);
            double[] rest = boneOffsets(scene, f, scene.config().warmup());
            double sign = f == 0 ? 1 : -1;
            for (int i = 0; i < rest.length; i += 3) {
                // about +y: (x, z) → (x cos θ + z sin θ, −x sin θ + z cos θ); y unchanged (to rounding, 1e-12 m)
                double c = Math.cos(sign * expected);
                double s = Math.sin(sign * expected);
                assertEquals(rest[i] * c + rest[i + 2] * s, turned[i], 1e-12, "finger " + f + " x");
                assertEquals(rest[i + 1], turned[i + 1], 1e-12, "finger " + f + " y");
                assertEquals(-rest[i] * s + rest[i + 2] * c, turned[i + 2], 1e-12, "finger " + f + " z");
            }
        }
    }

    @Test
    void theStraightSlideMovesTheBonesWithoutTurningThem() {
        SnapScene scene = scene("straight");
        double slide = PARAMS.windows().vs() * (PARAMS.windows().t3() - PARAMS.windows().t2());
        double end = scene.config().warmup() + 0.4;
        for (int f = 0; f < 2; f++) {
            double[] moved = bonePositions(scene, f, end);
            double[] before = bonePositions(scene, f, scene.config().warmup() + 0.12);
            for (int i = 0; i < moved.length; i += 3) {
                // the thumb (0) slides −x, the finger +x, by 2 mm; nothing else moves after the pinch
                assertEquals(before[i] + (f == 0 ? -slide : slide), moved[i], 1e-12);
                assertEquals(before[i + 1], moved[i + 1], 1e-12);
                assertEquals(before[i + 2], moved[i + 2], 1e-12);
            }
        }
    }

    /** Bone node positions of fingertip f at time t, relative to their centroid. */
    private static double[] boneOffsets(SnapScene scene, int f, double t) {
        double[] p = bonePositions(scene, f, t);
        double[] centre = new double[3];
        for (int i = 0; i < p.length; i++) {
            centre[i % 3] += 3.0 * p[i] / p.length;
        }
        for (int i = 0; i < p.length; i++) {
            p[i] -= centre[i % 3];
        }
        return p;
    }

    private static double[] bonePositions(SnapScene scene, int f, double t) {
        SoftWorld world = scene.world();
        double[] pos = world.restPositions().clone();
        new SoftSimulator(world, CardsConfig.solver(Path.of("configs/cards/solver.json")), scene.motion(PARAMS)).placeBones(t, pos);
        SoftBody tip = world.body(f == 0 ? "thumb" : "finger");
        return java.util.stream.IntStream.range(tip.firstNode(), tip.firstNode() + tip.nodeCount())
                .filter(world::isBone)
                .flatMap(n -> java.util.stream.IntStream.of(3 * n, 3 * n + 1, 3 * n + 2))
                .mapToDouble(i -> pos[i]).toArray();
    }
}
