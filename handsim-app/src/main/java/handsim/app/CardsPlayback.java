package handsim.app;

import handsim.cards.sim.Trajectory;
import handsim.cards.sleight.SnapTrial;
import handsim.config.Home;
import handsim.viewer.SurfacePlayer;
import handsim.viewer.ViewerConfig;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/** {@code view --scene snap}: plays a Card Snapping trajectory in the viewer's window. */
final class CardsPlayback {

    private CardsPlayback() {
    }

    /** The trajectory of a study's best trial, as {@code cards optimize} records it. */
    static Path bestTrajectory(Path study) {
        Path file = study.resolve(CardsOptimize.BEST_DIR).resolve("trajectory.json");
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException("--study " + study + " holds no " + CardsOptimize.BEST_DIR
                    + "/trajectory.json (is it a study folder of cards optimize, run to its end?)");
        }
        return file;
    }

    static int play(Path file, int maxFrames) {
        Trajectory t;
        if (file != null) {
            if (!Files.isRegularFile(file)) {
                throw new IllegalArgumentException("--trajectory " + file + " is not a file");
            }
            t = Trajectory.read(file);
        } else {
            System.out.println("handsim view: running the configured Card Snapping trial with coarse fingertips...");
            SnapTrial trial = SnapTrial.fromConfigs(Home.root(), "coarse", null);
            t = Trajectory.of(trial.scene().world());
            t.record(trial.heldState());
            Trajectory recording = t;
            trial.run(trial.scene().config().defaults(), (state, step) -> recording.record(state));
        }
        Trajectory shown = t;
        List<SurfacePlayer.Frame> frames = shown.frames().stream()
                .map(f -> new SurfacePlayer.Frame(f.time(), CardsCommand.surfaces(shown, f))).toList();
        ViewerConfig config = ViewerSession.config();
        int drawn = SurfacePlayer.play("handsim: Card Snapping", frames, CardsCommand.camera(config), config, 0.25, maxFrames);
        System.out.println("handsim view: drew " + drawn + " frames (a quarter of real time, looping)");
        return 0;
    }
}
