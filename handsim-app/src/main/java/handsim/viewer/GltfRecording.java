package handsim.viewer;

import handsim.export.ExportOptions;
import handsim.export.ExportTarget;
import handsim.export.MotionRecorder;
import handsim.scene.LiveFrame;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Optional;

/**
 * The viewer's glTF recording (key G): the frames the viewer draws are offered to a
 * {@link MotionRecorder}, which keeps one every 1 / {@code gltfRate} simulated seconds; stopping
 * writes them, with the floor, the goal and the camera where it stood when the recording began,
 * as one .glb ({@link ExportTarget}: moved into place whole).
 */
final class GltfRecording {

    private final ExportTarget target;
    private final ExportOptions options;
    private final MotionRecorder recorder;
    private final String title;

    /** A recording into {@code file} (checked now) seen from {@code camera}, titled after what is shown. */
    GltfRecording(Path file, ViewerConfig config, Camera camera, String title) {
        this.target = ExportTarget.of(file, "gltf", "recording file", "format");
        this.options = ExportLook.options(config, true, true, Optional.of(camera));
        this.recorder = new MotionRecorder(config.recording().gltfRate());
        this.title = title;
    }

    /** Keeps the frame if a sample is due at its simulated time. */
    void offer(LiveFrame f) {
        recorder.offer(f.snapshot(), f.goal());
    }

    int samples() {
        return recorder.sampleCount();
    }

    Path file() {
        return target.file();
    }

    /** Writes the samples so far; false when there are too few for an animation (two). */
    boolean write() throws IOException {
        if (recorder.sampleCount() < 2) {
            return false;
        }
        target.write(recorder.clip(title), options);
        return true;
    }
}
