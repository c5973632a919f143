package handsim.app;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.sim.Trajectory;
import handsim.cards.sleight.CardSleight;
import handsim.report.Outputs;
import handsim.viewer.Camera;
import handsim.viewer.FrameFolder;
import handsim.viewer.OffscreenRenderer;
import handsim.viewer.ViewerConfig;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * A card trial recorded and written out: its outcome and trajectory, printed, and written as
 * trajectory.json, PNG frames, a strip of five of them (thesis Fig. 4.8, 4.10) and result.json.
 */
final class CardsRecording {

    static final int STRIP_FRAMES = 5;

    /** A trial's outcome, the trajectory recorded while it ran, and one line of steps.csv per step. */
    record Recorded(CardSleight.Outcome outcome, Trajectory trajectory, List<String> steps) {
    }

    /** steps.csv's header: each step's simulated time (s), solver work, smallest gap (m), barrier stiffness κ and its cap, wall time (s) split. */
    static final String STEPS_HEADER = "step,time,newtonIterations,converged,lineSearchHalvings,factorisations,cgIterations,contacts,minGap,"
            + "kappa,kappaMax,assemblySeconds,contactSeconds,solveSeconds";

    private CardsRecording() {
    }

    /** Runs one trial of {@code sleight} from its start, recording every frameEvery-th state. */
    static Recorded record(CardSleight sleight, Map<String, Double> params) {
        Trajectory trajectory = Trajectory.of(sleight.world());
        trajectory.record(sleight.startState(params));
        int every = sleight.frameEvery();
        List<String> steps = new java.util.ArrayList<>();
        CardSleight.Outcome outcome = sleight.run(params, (state, step) -> {
            if (state.steps % every == 0) {
                trajectory.record(state);
            }
            steps.add(String.format(Locale.ROOT, "%d,%.4f,%d,%b,%d,%d,%d,%d,%.6e,%.6e,%.6e,%.4f,%.4f,%.4f", state.steps, state.time, step.newtonIterations,
                    step.unconvergedSteps == 0, step.lineSearchHalvings, step.factorisations, step.cgIterations, step.maxContacts, step.minGap,
                    state.kappa, state.kappaMax, step.assemblyNanos * 1e-9, step.contactNanos * 1e-9, step.solveNanos * 1e-9));
        });
        return new Recorded(outcome, trajectory, steps);
    }

    /** Prints what a trial did: the sleight's lines, the smallest gap, Newton iterations, the wall time and its split. */
    static void report(CardSleight.Outcome o) {
        o.report().forEach(System.out::println);
        var c = o.cost();
        System.out.printf(Locale.ROOT, "min gap     %.3e m over the run (%s)%n", c.minGap(), c.minGap() > 0 ? "no interpenetration" : "INTERPENETRATION");
        System.out.printf(Locale.ROOT, "newton      %d iterations over %d steps, %.0f per simulated second, %.3f s each; at most %d contacts%n",
                c.newtonIterations(), c.steps(), c.newtonIterations() / c.simulatedSeconds(), c.secondsPerIteration(), c.maxContacts());
        System.out.printf(Locale.ROOT, "            at most %d in one step, %d steps unconverged, %d line-search halvings%n",
                c.mostNewtonIterationsInAStep(), c.unconvergedSteps(), c.lineSearchHalvings());
        System.out.printf(Locale.ROOT, "wall time   %.1f s: assembly %.1f s, contact %.1f s, solve %.1f s%n", c.wallSeconds(),
                c.assemblySeconds(), c.contactSeconds(), c.solveSeconds());
    }

    /** result.json's content: the sleight, mesh, parameters, objectives, figures and cost. */
    static ObjectNode resultJson(CardSleight sleight, Map<String, Double> params, Recorded run, List<String> objectiveNames) {
        ObjectNode o = run.outcome().toJson(params, objectiveNames);
        o.put("sleight", sleight.name());
        o.put("mesh", sleight.meshName());
        o.put("card", sleight.inputs().get("card").asText());
        return o;
    }

    /** What a recording folder holds ({@link #write}). */
    static final String[] RECORDING = {"result.json", "trajectory.json", "steps.csv", "strip.png", "heights.png", "frames/"};

    /**
     * Writes trajectory.json and steps.csv, then (unless {@code width} is 0) frames/ and strip.png, and last
     * result.json, each atomically: a folder with result.json holds the whole recording.
     */
    static void write(Path out, Recorded run, ObjectNode result, CardViews.View view, int width, int height) throws IOException {
        Files.createDirectories(out);
        run.trajectory().write(out.resolve("trajectory.json"));
        System.out.println("wrote " + out.resolve("trajectory.json"));
        Outputs.writeString(out.resolve("steps.csv"), STEPS_HEADER + "\n" + String.join("\n", run.steps()) + "\n");
        System.out.println("wrote " + out.resolve("steps.csv") + " (each step's Newton iterations, contacts, smallest gap and wall time)");
        if (width > 0) {
            int n = renderFrames(run.trajectory(), view, out.resolve("frames"), width, height);
            System.out.println("wrote " + n + " frames to " + out.resolve("frames"));
            writeStrip(out.resolve("frames"), n, out.resolve("strip.png"));
            System.out.println("wrote " + out.resolve("strip.png") + " (" + STRIP_FRAMES + " frames, start to end)");
        }
        if (run.trajectory().surfaces().stream().anyMatch(s -> s.name().equals("card3"))) {
            LiftFigure.write(run.trajectory(), "Double Lift: rise of the top cards and the fingertips", out.resolve("heights.png"));
            System.out.println("wrote " + out.resolve("heights.png"));
        }
        Outputs.writeJson(out.resolve("result.json"), result);
        System.out.println("wrote " + out.resolve("result.json"));
    }

    /** Frames evenly spaced from the first to the last, side by side at half size. */
    static void writeStrip(Path frames, int count, Path file) throws IOException {
        BufferedImage strip = null;
        for (int k = 0; k < STRIP_FRAMES; k++) {
            int index = (int) Math.round((count - 1) * k / (double) (STRIP_FRAMES - 1));
            BufferedImage im = javax.imageio.ImageIO.read(frames.resolve(String.format("%05d.png", index)).toFile());
            int w = im.getWidth() / 2;
            int h = im.getHeight() / 2;
            if (strip == null) {
                strip = new BufferedImage(w * STRIP_FRAMES, h, BufferedImage.TYPE_INT_RGB);
            }
            Graphics2D g = strip.createGraphics();
            g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_BILINEAR);
            g.drawImage(im, k * w, 0, w, h, null);
            g.dispose();
        }
        Outputs.writePng(file, strip);
    }

    /** Renders every frame of a trajectory to DIR/00000.png, ... through the viewer's renderer. */
    static int renderFrames(Trajectory trajectory, CardViews.View view, Path dir, int width, int height) throws IOException {
        ViewerConfig config = ViewerSession.config();
        try (OffscreenRenderer renderer = new OffscreenRenderer(width, height, config); FrameFolder folder = new FrameFolder(dir)) {
            Camera camera = CardViews.camera(view);
            for (Trajectory.Frame f : trajectory.frames()) {
                var image = renderer.renderSurfaces(CardViews.surfaces(trajectory, f, view), camera);
                folder.add(() -> image);
            }
            return folder.count();
        }
    }
}
