package handsim.app;

import handsim.cards.sim.Trajectory;
import handsim.export.ExportTarget;
import handsim.export.SurfaceGltf;
import handsim.report.Outputs;
import handsim.viewer.SurfaceMesh;
import handsim.viewer.ViewerConfig;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * {@code export --scene snap|double-lift}: a recorded card trial as glTF 2.0, every card (a slab
 * of its thickness) and fingertip a mesh animated by morph targets ({@link SurfaceGltf}), in the
 * viewer's frame and colours; each file written atomically.
 */
final class CardsExport {

    private CardsExport() {
    }

    static int export(String scene, Path trajectoryFile, ExportTarget target) throws IOException {
        Trajectory t = Trajectory.read(trajectoryFile);
        if (t.frames().size() < 2) {
            throw new IllegalArgumentException(trajectoryFile + ": " + t.frames().size() + " frame(s); an animation needs two");
        }
        ViewerConfig config = ViewerSession.config();
        CardViews.View view = CardViews.of(scene, config);
        List<List<SurfaceMesh>> frames = new ArrayList<>();
        float[] times = new float[t.frames().size()];
        for (int i = 0; i < times.length; i++) {
            Trajectory.Frame f = t.frames().get(i);
            times[i] = (float) (f.time() - t.frames().get(0).time());
            frames.add(CardViews.surfaces(t, f, view));
        }
        List<SurfaceGltf.Surface> surfaces = new ArrayList<>();
        for (int s = 0; s < t.surfaces().size(); s++) {
            SurfaceMesh first = frames.get(0).get(s);
            List<float[]> positions = new ArrayList<>();
            for (List<SurfaceMesh> frame : frames) {
                positions.add(frame.get(s).positions());
            }
            surfaces.add(new SurfaceGltf.Surface(t.surfaces().get(s).name(), first.rgba(), first.triangles(), positions));
        }
        String title = "handsim " + scene + ": " + trajectoryFile.getFileName();
        long t0 = System.nanoTime();
        handsim.viewer.Camera camera = CardViews.camera(view);
        // near and far planes around the card scene's scale (the view stands centimetres from its target)
        var cameraView = new handsim.export.ExportOptions.CameraView(camera.eye(), camera.target, camera.fovY, 0.05 * camera.distance,
                100 * camera.distance);
        for (ExportTarget.FileContent file : SurfaceGltf.files(target, title, times, surfaces, config.stage().roughness(), cameraView)) {
            Outputs.write(file.file(), out -> out.write(file.bytes()));
            System.out.printf(Locale.ROOT, "wrote %s (%d bytes)%n", file.file(), file.bytes().length);
        }
        System.out.printf(Locale.ROOT, "%d surfaces, %d frames over %.2f simulated s (%.2f s to write)%n", surfaces.size(), times.length,
                times[times.length - 1], (System.nanoTime() - t0) * 1e-9);
        return 0;
    }
}
