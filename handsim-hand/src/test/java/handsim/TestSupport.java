package handsim;

import handsim.config.Home;
import handsim.config.Json;
import handsim.control.PdController;
import handsim.control.PdGains;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.model.ModelLoader;
import handsim.sim.ObjectSpec;
import handsim.sim.SimConfig;
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

    public static ObjectSpec object(String name) {
        return ObjectSpec.load(Home.resolve("configs/objects/" + name + ".json"));
    }

    /** The palm centre in the neutral pose (m, world). */
    public static Vec3 neutralPalm() {
        return new handsim.kin.Kinematics(model()).siteFrame(model().site("palm_center"), model().poseVector("neutral")).origin();
    }

    private static handsim.spec.RunConfigs configs;

    /** The shipped model and configs, parsed once (the tasks' definitions among them). */
    public static synchronized handsim.spec.RunConfigs configs() {
        if (configs == null) {
            configs = new handsim.spec.RunConfigs(handsim.config.ConfigSet.fromFiles());
        }
        return configs;
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
        return configs().height().newTask(goals);
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
}
