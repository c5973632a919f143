package handsim.app;

import handsim.cards.sim.Trajectory;
import handsim.cards.sleight.SnapTrial;
import handsim.config.Home;
import handsim.viewer.SurfacePlayer;
import handsim.viewer.ViewerConfig;
import java.nio.file.Path;
import java.util.List;

/** {@code view --scene snap|double-lift}: plays a card trial's trajectory in the viewer's window. */
final class CardsPlayback {

    private CardsPlayback() {
    }

    /**
     * Plays {@code file} (null: the configured Card Snapping trial, run first with coarse
     * fingertips), for {@code maxFrames} drawn frames when positive, and writes the last one to
     * {@code screenshot} when not null.
     */
    static int play(String scene, Path file, int maxFrames, Path screenshot) {
        Trajectory t;
        if (file != null) {
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
        ViewerConfig config = ViewerSession.config();
        CardViews.View view = CardViews.of(scene, config);
        List<SurfacePlayer.Frame> frames = shown.frames().stream()
                .map(f -> new SurfacePlayer.Frame(f.time(), CardViews.surfaces(shown, f, view))).toList();
        int drawn = SurfacePlayer.play("handsim: " + (scene.equals("snap") ? "Card Snapping" : "Double Lift"), frames, CardViews.camera(view),
                config, 0.25, maxFrames, screenshot);
        System.out.println("handsim view: drew " + drawn + " frames (a quarter of real time, looping)");
        if (screenshot != null) {
            System.out.println("handsim view: screenshot " + screenshot);
        }
        return 0;
    }
}
