package handsim;

import handsim.config.Home;
import handsim.config.Json;
import handsim.control.PdController;
import handsim.control.PdGains;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.model.ModelLoader;
import handsim.sim.ObjectSpec;
import handsim.sim.SimConfig;
import handsim.viewer.ViewerConfig;
import java.util.SplittableRandom;

/** Shared loading of the project's model and configs, and tolerance helpers, for tests. */
public final class TestSupport {

    private static HandModel model;

    private TestSupport() {
    }

    public static synchronized HandModel model() {
        if (model == null) {
            model = ModelLoader.load(Home.defaultModel());
        }
        return model;
    }

    public static SimConfig simConfig() {
        return SimConfig.load(Home.resolve("configs/sim.json"));
    }

    public static PdController pd(HandModel m) {
        return new PdController(m, PdGains.parse(Json.load(Home.resolve("configs/controller.json")).get("pd")));
    }

    /** The shipped drawing and viewer settings ({@code configs/viewer.json}). */
    public static ViewerConfig viewerConfig() {
        return ViewerConfig.load(Home.resolve("configs/viewer.json"));
    }

    public static ObjectSpec object(String name) {
        return ObjectSpec.load(Home.resolve("configs/objects/" + name + ".json"));
    }

    /** The palm centre in the neutral pose (m, world). */
    public static Vec3 neutralPalm() {
        return new handsim.kin.Kinematics(model()).siteFrame(model().site("palm_center"), model().poseVector("neutral")).origin();
    }

    /** The shipped tasks (configs/tasks). */
    public static handsim.task.Tasks tasks() {
        return new handsim.task.Tasks(handsim.control.ControllerConfig.load(Home.resolve("configs/controller.json")).nominalThrows(),
                neutralPalm(), simConfig().groundHeight());
    }

    /** Height task environments over the shipped configs, with actions mapped onto {@code space}. */
    public static handsim.train.ThrowEnvFactory heightEnvs(handsim.control.ThrowSpace space) {
        return heightEnvs(space, false);
    }

    /** The same, ending an episode at the first throw that misses its goal when {@code endAtFailedThrow}. */
    public static handsim.train.ThrowEnvFactory heightEnvs(handsim.control.ThrowSpace space, boolean endAtFailedThrow) {
        handsim.control.ControllerConfig cc = handsim.control.ControllerConfig.load(Home.resolve("configs/controller.json"));
        return new handsim.train.ThrowEnvFactory("height", object("sphere"), () -> heightTask(null), cc,
                handsim.task.EpisodeLimits.parse(Json.load(Home.resolve("configs/episode.json"))),
                handsim.task.LaunchDistribution.load(Home.resolve("configs/launch.json")), space,
                new handsim.train.ThrowEnv.Settings(5, -1, handsim.train.SpinShaping.NONE, endAtFailedThrow),
                new handsim.task.StateVector(handsim.task.StateVector.Encoding.PAPER, java.util.Optional.empty()));
    }

    /** The shipped height task aiming at {@code goals}, or at its config's range when null. */
    public static handsim.task.HeightTask heightTask(handsim.task.HeightGoals goals) {
        return tasks().height(goals);
    }

    /**
     * The viewer's catch-and-throw loop of the height task (goal 1.2 m) with the nominal
     * controller and {@code object}, from the episode of {@code seed}, on {@code sim} (the scene owns it).
     */
    public static handsim.scene.CatchLoopScene heightLoopScene(handsim.sim.Simulator sim, String object, long seed) {
        handsim.control.ControllerConfig cc = handsim.control.ControllerConfig.load(Home.resolve("configs/controller.json"));
        handsim.evaluation.CatchEvaluation evaluation = handsim.evaluation.CatchEvaluation.nominal(cc,
                handsim.task.EpisodeLimits.parse(Json.load(Home.resolve("configs/episode.json"))),
                handsim.task.LaunchDistribution.load(Home.resolve("configs/launch.json")), object(object),
                heightTask(handsim.task.HeightGoals.fixed(1.2)));
        return new handsim.scene.CatchLoopScene(sim, evaluation, seed, new handsim.scene.HeightControl(0.05, 0.8, 1.7));
    }

    /** Uniform random joint angles inside the limits, shrunk by {@code margin} rad on each side. */
    public static double[] randomPose(HandModel m, SplittableRandom rng, double margin) {
        double[] q = new double[m.dofCount()];
        for (int i = 0; i < q.length; i++) {
            var d = m.dofs().get(i);
            double lo = d.lower() + margin, hi = d.upper() - margin;
            q[i] = lo + rng.nextDouble() * (hi - lo);
        }
        return q;
    }

    public static Vec3 randomUnit(SplittableRandom rng) {
        while (true) {
            Vec3 v = new Vec3(2 * rng.nextDouble() - 1, 2 * rng.nextDouble() - 1, 2 * rng.nextDouble() - 1);
            double n = v.norm();
            if (n > 0.1 && n < 1) {
                return v.times(1 / n);
            }
        }
    }

    public static Quat randomRotation(SplittableRandom rng) {
        return Quat.fromAxisAngle(randomUnit(rng), Math.PI * rng.nextDouble());
    }
}
