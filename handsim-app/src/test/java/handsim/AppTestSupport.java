package handsim;

import handsim.config.Home;
import handsim.viewer.ViewerConfig;

/** Shared loading of the application's configs and scenes for tests (the hand's: {@link TestSupport}). */
public final class AppTestSupport {

    private AppTestSupport() {
    }

    /** The shipped drawing and viewer settings ({@code configs/viewer.json}). */
    public static ViewerConfig viewerConfig() {
        return ViewerConfig.load(Home.resolve("configs/viewer.json"));
    }

    /**
     * The viewer's catch-and-throw loop of the height task (goal 1.2 m) with the nominal
     * controller and {@code object}, from the episode of {@code seed}, on {@code sim} (the scene owns it).
     */
    public static handsim.scene.CatchLoopScene heightLoopScene(handsim.sim.Simulator sim, String object, long seed) {
        handsim.scene.HeightControl control = new handsim.scene.HeightControl(0.05, 0.8, 1.7);
        handsim.taskdef.SteeredTask steered = TestSupport.configs().height().steered(object, handsim.task.HeightGoals.fixed(1.2),
                control.min(), control.max());
        handsim.spec.RunConfigs c = TestSupport.configs();
        handsim.evaluation.CatchEvaluation evaluation = handsim.evaluation.CatchEvaluation.nominal(c.controller(), c.limits(),
                c.launches(), c.object(object), steered.task());
        return new handsim.scene.CatchLoopScene(sim, evaluation, steered, seed, control, null);
    }
}
