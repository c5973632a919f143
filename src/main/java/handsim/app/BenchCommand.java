package handsim.app;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.kin.Frame;
import handsim.model.HandModel;
import handsim.model.Site;
import handsim.sim.ObjectSpec;
import handsim.sim.SimConfig;
import handsim.sim.Simulator;
import handsim.task.HeldBallScenario;
import handsim.task.ServoLoop;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code handsim bench}: headless physics throughput of the full arm+hand holding a pose while
 * a sphere is thrown into the palm and held (the {@link HeldBallScenario}).
 */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = "Measure physics steps per second, real-time factor and allocation rate of the arm+hand "
                + "holding a pose while a sphere is thrown into the palm and held.")
final class BenchCommand implements Callable<Integer> {

    @Option(names = "--seconds", paramLabel = "S", defaultValue = "10",
            description = "simulated seconds to measure, after 1 s of warm-up (default: ${DEFAULT-VALUE})")
    double seconds;

    @Option(names = "--iterations", paramLabel = "N",
            description = "quickStep iterations (default: configs/sim.json)")
    Integer iterations;

    @Option(names = "--json", paramLabel = "FILE", description = "write the figures as JSON")
    Path json;

    @Override
    public Integer call() throws Exception {
        if (!(seconds > 0 && seconds <= 3600)) {
            throw new IllegalArgumentException("--seconds must be in (0, 3600], got " + seconds);
        }
        if (iterations != null && (iterations < 1 || iterations > 1000)) {
            throw new IllegalArgumentException("--iterations must be in [1, 1000], got " + iterations);
        }
        HandModel model = Runtime.model(null);
        SimConfig config = Runtime.simConfig();
        if (iterations != null) {
            config = config.withSolverIterations(iterations);
        }
        ObjectSpec ball = Runtime.object("sphere");
        try (Simulator sim = Runtime.simulator(model, config)) {
            HeldBallScenario scenario = new HeldBallScenario(new ServoLoop(sim, Runtime.pd(model)), ball, 0.2, 1);
            int warmup = (int) Math.round(1.0 / config.timeStep());
            int measured = (int) Math.round(seconds / config.timeStep());
            for (int i = 0; i < warmup; i++) {
                scenario.step();
            }
            var threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
            long thread = Thread.currentThread().getId();
            long bytes0 = threads.getThreadAllocatedBytes(thread);
            long t0 = System.nanoTime();
            int reportEvery = Math.max(1, measured / 10);
            for (int i = 0; i < measured; i++) {
                scenario.step();
                if ((i + 1) % reportEvery == 0) {
                    System.out.printf("  %3.0f%%  simulated %.1f s%n", 100.0 * (i + 1) / measured, sim.time());
                }
            }
            double wall = (System.nanoTime() - t0) / 1e9;
            long bytes = threads.getThreadAllocatedBytes(thread) - bytes0;
            double stepsPerS = measured / wall;
            Site palm = model.site("palm_center");
            Frame palmFrame = sim.bodyFrame(palm.body()).compose(new Frame(palm.position(), palm.orientation()));
            double ballToPalm = palmFrame.origin().distance(sim.objectState().position());
            boolean held = sim.handContacts().any() && ballToPalm < 0.06;
            ObjectNode out = JsonNodeFactory.instance.objectNode();
            out.put("scenario", "held_ball");
            out.put("steps", measured);
            out.put("time_step_s", config.timeStep());
            out.put("solver_iterations", config.solverIterations());
            out.put("wall_s", wall);
            out.put("steps_per_s", stepsPerS);
            out.put("realtime_factor", stepsPerS * config.timeStep());
            out.put("bytes_per_step", (double) bytes / measured);
            out.put("allocation_mb_per_s", bytes / wall / 1e6);
            out.put("ball_held", held);
            out.put("ball_to_palm_m", ballToPalm);
            out.put("hand_contact_points", sim.handContacts().points());
            System.out.printf("%d steps of %.1f ms in %.2f s: %.0f steps/s, %.2fx real time, %.0f bytes/step; "
                    + "quickStep iterations %d; ball %s (%.3f m from the palm centre, %d contact points)%n",
                    measured, config.timeStep() * 1e3, wall, stepsPerS, stepsPerS * config.timeStep(),
                    (double) bytes / measured, config.solverIterations(), held ? "held" : "NOT held", ballToPalm,
                    sim.handContacts().points());
            if (json != null) {
                Outputs.writeJson(json, out);
                System.out.println("wrote " + json);
            }
            return held ? 0 : 1;
        }
    }
}
