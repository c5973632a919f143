package handsim.task;

import handsim.evaluation.CatchEvaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.TestSupport;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.ControllerConfig;
import handsim.math.Vec3;
import handsim.sim.SimulationDiverged;
import handsim.sim.Simulator;
import handsim.sim.ode.OdeSimulator;
import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Proxy;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Integration of controller and physics: a sphere thrown toward the hand (seed 1 of
 * configs/launch.json) is caught on its first arrival and thrown and caught again, and the
 * loop follows a recorded golden trajectory.
 */
@Tag("slow")
public class CatchLoopTest {

    static final long SEED = 1;
    static final Path GOLDEN = Path.of("handsim-hand/src/test/resources/golden/sphere_seed1_loop.csv");
    /** Golden rows every 25 controller ticks (50 ms). */
    static final int ROW_EVERY = 25;
    /**
     * The same build replays a seed bit for bit (OdeSimulatorTest); 1 mm leaves room for last-bit
     * differences of another JDK's maths intrinsics, while a change to the controller, the model
     * or the physics moves palm and ball by centimetres within the loop. The golden loop was
     * recorded with ode4j's quickStep; handsim's step, the default, whose bits differ from it in
     * rounding, stays within the same 1 mm over this one loop.
     */
    static final double PALM_TOLERANCE = 1e-3;
    static final double OBJECT_TOLERANCE = 1e-3;
    /** Natural motion: joint limits exceeded by at most 2 degrees, penetration at most 5 mm. */
    static final double MAX_LIMIT_EXCESS = Math.toRadians(2);
    static final double MAX_PENETRATION = 0.005;

    @Test
    void sphereIsCaughtOnFirstArrivalAndALoopCompletesFollowingTheGoldenTrajectory() throws IOException {
        List<String> rows = new ArrayList<>();
        EpisodeResult result;
        try (Simulator sim = new OdeSimulator(TestSupport.model(), TestSupport.simConfig())) {
            CatchEvaluation evaluation = evaluation();
            CatchThrowEpisode episode = evaluation.start(sim, SEED);
            int ticks = 0;
            // first catch, then one throw and its catch: two loop records
            while (episode.status() == CatchThrowEpisode.Status.RUNNING && episode.loops().size() < 2) {
                if (ticks++ % ROW_EVERY == 0) {
                    rows.add(row(episode));
                }
                evaluation.tick(episode, SEED);
            }
            result = episode.result(SEED);
        }
        assertTrue(result.firstCatch(), "caught on the first arrival");
        assertTrue(result.loopsCompleted() >= 1, "one catch-throw-catch loop; got " + result);
        assertTrue(result.maxLimitExcess() < MAX_LIMIT_EXCESS, "limit excess " + Math.toDegrees(result.maxLimitExcess()) + " deg");
        assertTrue(result.maxPenetration() < MAX_PENETRATION, "penetration " + result.maxPenetration() + " m");
        assertTrue(result.peakTorqueRatio() <= 1 + 1e-9, "torques within the human limits: " + result.peakTorqueRatio());

        Path golden = Home.root().resolve(GOLDEN);
        if (Boolean.getBoolean("handsim.regenerateGolden")) {
            Files.writeString(golden, "time,phase,palm_x,palm_y,palm_z,object_x,object_y,object_z\n" + String.join("\n", rows) + "\n");
            // a file compared with what was just written to it proves nothing: the run that records reports skipped
            org.junit.jupiter.api.Assumptions.abort("golden loop re-recorded to " + GOLDEN + ", not compared: review its diff");
        }
        List<String> expected = Files.readAllLines(golden);
        assertEquals(expected.size() - 1, rows.size(), "golden rows (regenerate with scripts/regenerate-golden)");
        for (int i = 0; i < rows.size(); i++) {
            String[] want = expected.get(i + 1).split(","), got = rows.get(i).split(",");
            String at = "golden row " + (i + 1) + " (t = " + want[0] + " s)";
            assertEquals(want[1], got[1], at + ": FSM state");
            assertTrue(point(want, 2).distance(point(got, 2)) < PALM_TOLERANCE, at + ": palm " + rows.get(i));
            assertTrue(point(want, 5).distance(point(got, 5)) < OBJECT_TOLERANCE, at + ": object " + rows.get(i));
        }
    }

    /**
     * Long objects, five seeded launches each (seeds 1000-1004 of configs/launch.json): at least
     * four caught on the first arrival. A regression guard for the grasps and the heading search,
     * not the benchmark: over 100 launches the shipped configs catch 98 % of cans, 98 % of
     * cuboids and 87 % of clubs (docs/results.md), the paper's open and closed poses 12 %, 32 %
     * and 0 % (docs/design.md).
     */
    @ParameterizedTest
    @ValueSource(strings = {"can", "cuboid", "club"})
    void longObjectsAreCaughtOnFirstArrival(String object) {
        int caught = 0;
        StringBuilder outcomes = new StringBuilder();
        try (Simulator sim = new OdeSimulator(TestSupport.model(), TestSupport.simConfig())) {
            for (long seed = 1000; seed < 1005; seed++) {
                EpisodeResult r = evaluation(object).run(sim, seed, 0, null);
                caught += r.firstCatch() ? 1 : 0;
                outcomes.append(seed).append(r.firstCatch() ? " caught; " : " dropped; ");
                assertTrue(r.maxLimitExcess() < MAX_LIMIT_EXCESS, "limit excess " + Math.toDegrees(r.maxLimitExcess()) + " deg");
                assertTrue(r.maxPenetration() < MAX_PENETRATION, "penetration " + r.maxPenetration() + " m");
            }
        }
        assertTrue(caught >= 4, object + ": " + outcomes);
    }

    @Test
    void aDivergenceNamesTheEpisodesSeedAndLoopSoTheRunCanBeReplayed() {
        // the real engine, except that its 3,000th step (0.6 s, before the throw-in's catch is judged) reports a
        // divergence as OdeSimulator does
        try (OdeSimulator engine = new OdeSimulator(TestSupport.model(), TestSupport.simConfig())) {
            int[] steps = {0};
            Simulator failing = (Simulator) Proxy.newProxyInstance(Simulator.class.getClassLoader(), new Class<?>[] {Simulator.class},
                    (proxy, method, args) -> {
                        if (method.getName().equals("step") && ++steps[0] == 3000) {
                            throw new SimulationDiverged("body palm spins at 9999 rad/s");
                        }
                        try {
                            return method.invoke(engine, args);
                        } catch (InvocationTargetException e) {
                            throw e.getCause();
                        }
                    });
            SimulationDiverged e = assertThrows(SimulationDiverged.class, () -> evaluation().run(failing, 17, 3, null));
            assertEquals("episode of seed 17, loop 0: body palm spins at 9999 rad/s", e.getMessage());
            steps[0] = 0;
            e = assertThrows(SimulationDiverged.class, () -> evaluation().runWhileSuccessful(failing, 18, 3));
            assertTrue(e.getMessage().startsWith("episode of seed 18, loop 0: "), e.getMessage());
        }
    }

    public static CatchEvaluation evaluation() {
        return evaluation("sphere");
    }

    static CatchEvaluation evaluation(String object) {
        ControllerConfig cc = ControllerConfig.load(Home.resolve("configs/controller.json"));
        return CatchEvaluation.nominal(cc, EpisodeLimits.parse(Json.load(Home.resolve("configs/episode.json"))),
                LaunchDistribution.load(Home.resolve("configs/launch.json")), TestSupport.object(object),
                TestSupport.heightTask(HeightGoals.fixed(1.2)));
    }

    private static String row(CatchThrowEpisode e) {
        var obs = e.observe();
        Vec3 p = obs.palm().origin(), o = obs.object().position();
        return String.format(Locale.ROOT, "%.4f,%s,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f", obs.time(), e.controllerState().phase(),
                p.x(), p.y(), p.z(), o.x(), o.y(), o.z());
    }

    private static Vec3 point(String[] cells, int from) {
        return new Vec3(Double.parseDouble(cells[from]), Double.parseDouble(cells[from + 1]), Double.parseDouble(cells[from + 2]));
    }
}
