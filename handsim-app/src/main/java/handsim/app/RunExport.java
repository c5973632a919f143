package handsim.app;

import handsim.evaluation.CatchEvaluation;
import handsim.export.ExportTarget;
import handsim.export.MotionRecorder;
import handsim.sim.Simulator;
import handsim.task.Goal;
import handsim.viewer.Camera;
import handsim.viewer.ExportLook;
import handsim.viewer.ViewerConfig;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Optional;

/**
 * {@code --export FILE} of a headless run ({@code demo --headless}, {@code evaluate --episodes 1}):
 * the file is checked before the run, the run's ticks are sampled as they pass at the viewer's
 * glTF rate ({@code configs/viewer.json} recording.gltfRate), and the animation (glTF or BVH by
 * the file's extension, with the floor and the viewer's home camera) is written when the run is
 * over.
 */
final class RunExport implements CatchEvaluation.TickWatcher {

    private final ExportTarget target;
    private final ViewerConfig config = ViewerSession.config();
    private final MotionRecorder recorder = new MotionRecorder(config.recording().gltfRate());

    private RunExport(ExportTarget target) {
        this.target = target;
    }

    /** The export to {@code file}, checked now; null when no file is given. */
    static RunExport to(Path file) {
        if (file == null) {
            return null;
        }
        new OutputPaths().file("--export", file).check(); // first: the folder it makes is given up again if the run fails
        ExportTarget target = ExportTarget.of(file, null, "--export", "--export");
        new OutputPaths().files("--export", target.files()).check();
        return new RunExport(target);
    }

    @Override
    public void afterTick(Simulator sim) {
        if (recorder.due(sim.time())) {
            recorder.record(sim.snapshot(), new Goal.None());
        }
    }

    /** Writes what was recorded as the animation {@code title}, and says so. */
    void write(String title) throws IOException {
        target.write(recorder.clip(title), ExportLook.options(config, true, false, Optional.of(new Camera(config.camera()))));
        System.out.printf("wrote %s (%d samples at %s Hz)%n", target.file(), recorder.sampleCount(), recorder.rate());
    }
}
