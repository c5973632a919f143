package handsim.app;

import handsim.export.ExportOptions;
import handsim.export.ExportTarget;
import handsim.export.MotionClip;
import handsim.export.MotionRecorder;
import handsim.scene.Scene;
import handsim.viewer.Camera;
import handsim.viewer.ExportLook;
import handsim.viewer.ViewerConfig;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code handsim export}: a headless run of the scene {@code render} draws ({@link SceneOptions}),
 * sampled {@code --rate} times a simulated second and written as glTF 2.0 or BVH
 * ({@link handsim.export}). The request is checked before anything is simulated.
 */
@Command(name = "export", mixinStandardHelpOptions = true,
        description = "Write a headless run's animation for Blender, Unity, Unreal or a web page: glTF 2.0 (FILE.glb, or "
                + "FILE.gltf with FILE.bin; the arm and hand as a node hierarchy with meshes, the object as its own node) or BVH "
                + "(the skeleton with the model's Euler channels, the object as a second root). Takes the scene options of render; "
                + "with --scene snap|double-lift a recorded card trial instead, as glTF with morph-target animation.")
final class ExportCommand implements Callable<Integer> {

    /** The highest sampling rate: below the controller's 500 Hz, so that every sample is a new state. */
    static final double MAX_RATE = 240;

    @Option(names = "--out", paramLabel = "FILE", required = true, description = "the file: .glb, .gltf (with a .bin beside it) or .bvh")
    Path out;

    @Option(names = "--format", description = "gltf or bvh (default: from the file's extension)")
    String format;

    @Option(names = "--rate", paramLabel = "HZ", defaultValue = "60", description = "samples per simulated second (default: ${DEFAULT-VALUE})")
    double rate;

    @Option(names = "--floor", description = "glTF: add the checkered floor")
    boolean floor;

    @Option(names = "--goal", description = "glTF: add the task's goal (the height plane or the box)")
    boolean goal;

    @Option(names = "--camera", description = "glTF: add a camera at the viewer's home view (configs/viewer.json)")
    boolean camera;

    @Mixin
    SceneOptions scene;

    @Mixin
    CardsSceneChoice cards;

    @Override
    public Integer call() throws Exception {
        if (cards.given()) {
            Path file = cards.file(true);
            new OutputPaths().file("--out", out).check(); // first: the folder it makes is given up again if the export fails
            ExportTarget target = ExportTarget.of(out, format, "--out", "--format");
            if (target.format() != ExportTarget.Format.GLTF) {
                throw new IllegalArgumentException("--out: a card trial is exported as glTF (.glb or .gltf), got " + out);
            }
            new OutputPaths().files("--out", target.files()).check();
            return CardsExport.export(cards.scene, file, target);
        }
        scene.validate();
        if (!(rate > 0 && rate <= MAX_RATE)) {
            throw new IllegalArgumentException("--rate must be in (0, " + (int) MAX_RATE + "] Hz, got " + rate);
        }
        MotionRecorder recorder = new MotionRecorder(rate);
        int samples = recorder.samplesOver(scene.seconds);
        if (samples < 2) {
            throw new IllegalArgumentException(String.format(Locale.ROOT, "--seconds %s is shorter than one sample at --rate %s Hz "
                    + "(an animation needs two)", scene.seconds, rate));
        }
        new OutputPaths().file("--out", out).check(); // first: the folder it makes is given up again if the export fails
        ExportTarget target = ExportTarget.of(out, format, "--out", "--format");
        new OutputPaths().files("--out", target.files()).check();
        ViewerConfig config = ViewerSession.config();
        ExportOptions options = ExportLook.options(config, floor, goal, camera ? Optional.of(new Camera(config.camera())) : Optional.empty());
        long t0 = System.nanoTime();
        MotionClip clip;
        try (Scene shown = scene.open("export", config)) {
            clip = record(shown, recorder, samples, "handsim: " + SceneOptions.describe(shown));
        }
        double simulated = (System.nanoTime() - t0) / 1e9;
        target.write(clip, options);
        double written = (System.nanoTime() - t0) / 1e9 - simulated;
        System.out.printf(Locale.ROOT, "wrote %s: %d samples at %s Hz over %.2f simulated s (%.2f s to simulate, %.2f s to write)%n",
                String.join(" and ", target.files().stream().map(Path::toString).toList()), clip.samples().size(), rate,
                clip.duration(), simulated, written);
        return 0;
    }

    /** Advances {@code scene} from one sample time to the next, {@code samples} times. */
    static MotionClip record(Scene scene, MotionRecorder recorder, int samples, String title) {
        recorder.offer(scene.snapshot(), SceneOptions.goal(scene));
        while (recorder.sampleCount() < samples) {
            scene.advance(recorder.untilNext());
            recorder.offer(scene.snapshot(), SceneOptions.goal(scene));
        }
        return recorder.clip(title);
    }
}
