package handsim.app;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.sim.SoftBody;
import handsim.cards.sim.Trajectory;
import handsim.cards.sleight.SnapParams;
import handsim.cards.sleight.SnapResult;
import handsim.cards.sleight.SnapTrial;
import handsim.config.Home;
import handsim.config.Json;
import handsim.math.Vec3;
import handsim.report.Outputs;
import handsim.viewer.Camera;
import handsim.viewer.FrameFolder;
import handsim.viewer.OffscreenRenderer;
import handsim.viewer.SurfaceMesh;
import handsim.viewer.ViewerConfig;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code handsim cards}: the soft-body card sleights (thesis sec. 3.2 and 4.2). */
@Command(name = "cards", mixinStandardHelpOptions = true,
        description = "Soft fingertips handle thin-shell playing cards (thesis 3.2, 4.2).",
        subcommands = {CardsCommand.Snap.class, CardsOptimize.class})
final class CardsCommand implements Runnable {

    @Override
    public void run() {
        new picocli.CommandLine(this).usage(System.out);
    }

    /** {@code handsim cards snap}: one Card Snapping trial. */
    @Command(name = "snap", mixinStandardHelpOptions = true,
            description = "Run one Card Snapping trial (thesis 4.2.4): print the end angle between the cards, the objective, "
                    + "the smallest gap, Newton iterations and wall time; write the trajectory and PNG frames to --out.")
    static final class Snap implements Callable<Integer> {

        @Option(names = "--params", paramLabel = "FILE", description = "JSON with t0, t1, vp, t2, t3, vs (default: the params of configs/cards/snap.json)")
        Path params;

        @Option(names = "--out", paramLabel = "DIR", description = "folder for result.json, trajectory.json and frames/ (default: none written)")
        Path out;

        @Mixin
        CardsSceneOptions scene;

        @Override
        public Integer call() throws IOException {
            scene.checkFrameSize();
            new OutputPaths().heldFolder("--out", out, RECORDING).check();
            SnapTrial trial = SnapTrial.fromConfigs(Home.root(), scene.mesh, scene.card);
            SnapParams p = params == null ? trial.scene().config().defaults() : SnapParams.parse(Json.load(params));
            p.validate(trial.scene().config().duration(), params == null ? null : params.toString());
            System.out.printf("handsim cards snap: %s fingertips, %d nodes (%d free), %s cards%n", trial.scene().config().meshName(),
                    trial.scene().world().nodeCount(), trial.scene().world().freeNodeCount(), scene.card == null ? "default" : scene.card);
            long h0 = System.nanoTime();
            trial.heldState();
            System.out.printf("hold (warm-up checkpoint): %.1f s wall%n", (System.nanoTime() - h0) * 1e-9);
            Recorded run = record(trial, p);
            report(run.result(), trial);
            if (out != null) {
                write(out, run, p, trial, scene.frameWidth(), scene.height);
            }
            return 0;
        }
    }

    /** What a recording folder holds ({@link #writeRecording}). */
    static final String[] RECORDING = {"result.json", "trajectory.json", "strip.png", "frames/"};

    /** A trial's result and the trajectory recorded while it ran. */
    record Recorded(SnapResult result, Trajectory trajectory) {
    }

    /** Runs one trial from the hold, recording every {@code frameEvery}-th state. */
    static Recorded record(SnapTrial trial, SnapParams p) {
        Trajectory trajectory = Trajectory.of(trial.scene().world());
        trajectory.record(trial.heldState());
        int every = trial.scene().config().frameEvery();
        SnapResult r = trial.run(p, (state, step) -> {
            if (state.steps % every == 0) {
                trajectory.record(state);
            }
        });
        return new Recorded(r, trajectory);
    }

    static void report(SnapResult r, SnapTrial trial) {
        System.out.printf("alpha_end   %.3f deg (target %.1f)%n", r.alphaEnd(), trial.scene().config().alphaTargetDegrees());
        System.out.printf("objective   %.3f deg%n", r.objective());
        System.out.printf("min gap     %.3e m over the run (%s)%n", r.minGap(), r.minGap() > 0 ? "no interpenetration" : "INTERPENETRATION");
        System.out.printf("card drop   %.2f mm below the hold at the end (%s)%n", 1e3 * r.cardDrop(), r.held() ? "held" : "DROPPED: no snap");
        System.out.printf("newton      %d iterations over %d steps, %.0f per simulated second%n", r.newtonIterations(), r.steps(),
                r.newtonIterationsPerSimulatedSecond());
        System.out.printf("wall time   %.1f s: assembly %.1f s, contact %.1f s, solve %.1f s%n", r.wallSeconds(), r.assemblySeconds(),
                r.contactSeconds(), r.solveSeconds());
    }

    /** The result's figures as JSON (what result.json holds besides the params). */
    static ObjectNode resultJson(SnapResult r, SnapParams p, SnapTrial trial) {
        ObjectNode o = Json.mapper().createObjectNode();
        o.set("params", p.toJson());
        o.put("mesh", trial.scene().config().meshName());
        o.put("alphaEndDegrees", r.alphaEnd());
        o.put("alphaTargetDegrees", trial.scene().config().alphaTargetDegrees());
        o.put("objectiveDegrees", r.objective());
        o.put("minGap", r.minGap());
        o.put("cardDrop", r.cardDrop());
        o.put("held", r.held());
        o.put("steps", r.steps());
        o.put("newtonIterations", r.newtonIterations());
        o.put("wallSeconds", r.wallSeconds());
        o.put("assemblySeconds", r.assemblySeconds());
        o.put("contactSeconds", r.contactSeconds());
        o.put("solveSeconds", r.solveSeconds());
        return o;
    }

    /**
     * Writes trajectory.json, then (unless {@code width} is 0) frames/ and strip.png, and last
     * result.json, each atomically: a folder with result.json holds the whole recording.
     */
    static void write(Path out, Recorded run, SnapParams p, SnapTrial trial, int width, int height) throws IOException {
        writeRecording(out, run, resultJson(run.result(), p, trial), width, height);
    }

    static void writeRecording(Path out, Recorded run, ObjectNode result, int width, int height) throws IOException {
        Files.createDirectories(out);
        run.trajectory().write(out.resolve("trajectory.json"));
        System.out.println("wrote " + out.resolve("trajectory.json"));
        if (width > 0) {
            int n = renderFrames(run.trajectory(), out.resolve("frames"), width, height);
            System.out.println("wrote " + n + " frames to " + out.resolve("frames"));
            writeStrip(out.resolve("frames"), n, out.resolve("strip.png"));
            System.out.println("wrote " + out.resolve("strip.png") + " (" + STRIP_FRAMES + " frames, start to end)");
        }
        Outputs.writeString(out.resolve("result.json"), Json.pretty(result) + "\n");
        System.out.println("wrote " + out.resolve("result.json"));
    }

    static final int STRIP_FRAMES = 5;



    /** Frames evenly spaced from the first to the last, side by side at half size (like thesis Fig. 4.8). */
    static void writeStrip(Path frames, int count, Path file) throws IOException {
        java.awt.image.BufferedImage strip = null;
        for (int k = 0; k < STRIP_FRAMES; k++) {
            int index = (int) Math.round((count - 1) * k / (double) (STRIP_FRAMES - 1));
            java.awt.image.BufferedImage im = javax.imageio.ImageIO.read(frames.resolve(String.format("%05d.png", index)).toFile());
            int w = im.getWidth() / 2;
            int h = im.getHeight() / 2;
            if (strip == null) {
                strip = new java.awt.image.BufferedImage(w * STRIP_FRAMES, h, java.awt.image.BufferedImage.TYPE_INT_RGB);
            }
            java.awt.Graphics2D g = strip.createGraphics();
            g.setRenderingHint(java.awt.RenderingHints.KEY_INTERPOLATION, java.awt.RenderingHints.VALUE_INTERPOLATION_BILINEAR);
            g.drawImage(im, k * w, 0, w, h, null);
            g.dispose();
        }
        FrameFolder.writePng(strip, file);
    }

    /** Renders every frame of a trajectory to DIR/00000.png, ... through the viewer's renderer. */
    static int renderFrames(Trajectory trajectory, Path dir, int width, int height) throws IOException {
        ViewerConfig config = ViewerSession.config();
        try (OffscreenRenderer renderer = new OffscreenRenderer(width, height, config); FrameFolder folder = new FrameFolder(dir)) {
            Camera camera = camera(config);
            for (Trajectory.Frame f : trajectory.frames()) {
                var image = renderer.renderSurfaces(surfaces(trajectory, f), camera);
                folder.add(() -> image);
            }
            return folder.count();
        }
    }

    /** The card scene's camera: looking at the cards' upper half from the thumb's side, slightly above. */
    static Camera camera(ViewerConfig config) {
        ViewerConfig.CameraHome h = config.camera();
        return new Camera(new ViewerConfig.CameraHome(new Vec3(0, 0.0, 0), Math.toRadians(35), Math.toRadians(15), 0.16,
                h.fovY(), 0.06, 1.0, h.orbitPerPixel(), h.panPerPixel(), h.zoomPerScroll(), h.followRate()));
    }

    private static final float[] CARD_FRONT = {0.93f, 0.93f, 0.90f, 1};
    private static final float[] CARD_BACK = {0.75f, 0.20f, 0.18f, 1};
    private static final float[] SKIN = {0.87f, 0.68f, 0.56f, 1};

    /** A frame's surfaces in the viewer's frame: card world (x, y, z up) to viewer (x, z, −y). */
    static List<SurfaceMesh> surfaces(Trajectory trajectory, Trajectory.Frame frame) {
        List<SurfaceMesh> out = new ArrayList<>();
        int cards = 0;
        for (int s = 0; s < trajectory.surfaces().size(); s++) {
            Trajectory.Surface surface = trajectory.surfaces().get(s);
            double[] p = frame.positions().get(s);
            float[] v = new float[p.length];
            for (int i = 0; i < p.length / 3; i++) {
                v[3 * i] = (float) p[3 * i];
                v[3 * i + 1] = (float) p[3 * i + 2];
                v[3 * i + 2] = (float) -p[3 * i + 1];
            }
            boolean card = surface.kind() == SoftBody.Kind.CARD;
            float[] colour = card ? (cards++ == 0 ? CARD_FRONT : CARD_BACK) : SKIN;
            out.add(new SurfaceMesh(v, surface.triangles(), colour, card));
        }
        return out;
    }
}
