package handsim.app;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.sim.SimConfig;
import handsim.sim.StepAccounting;
import java.util.List;

/** What one bench worker measured, and the totals and printout of a pass of them. */
record BenchRun(long steps, double wallS, double cpuS, double stolenS, long bytes, StepAccounting engine, int episodes,
        int loopsCaught, int firstCatches, boolean held, double ballToPalm) {

    double stepsPerSecond() {
        return steps / wallS;
    }

    /** Slices of one world run one after another, as one run, with its episodes, catches and first catches. */
    static BenchRun sequence(List<BenchRun> slices, int[] counts) {
        long steps = 0, bytes = 0;
        double wall = 0, cpu = 0, stolen = 0;
        StepAccounting engine = new StepAccounting();
        for (BenchRun r : slices) {
            steps += r.steps();
            wall += r.wallS();
            cpu += r.cpuS();
            stolen += r.stolenS();
            bytes += r.bytes();
            StepAccounting e = r.engine();
            engine.add(e.stepNanos(), e.collisionNanos(), e.solverNanos(), e.engineBytes(), e.solverBytes());
        }
        return new BenchRun(steps, wall, cpu, stolen, bytes, engine, counts[0], counts[1], counts[2], false, Double.NaN);
    }

    /**
     * Totals of one pass: steps/s is the sum of the workers' steps over the longest worker's
     * wall time (all start together), steps per CPU second is less sensitive to other load.
     */
    static ObjectNode summarize(List<BenchRun> runs, SimConfig config) {
        long steps = 0, bytes = 0, engineBytes = 0, solverBytes = 0, stepNs = 0, collisionNs = 0, solverNs = 0;
        double wallSum = 0;
        double wall = 0, cpu = 0, stolen = 0;
        int episodes = 0, caught = 0, firstCatches = 0;
        boolean held = true;
        double ballToPalm = 0;
        for (BenchRun r : runs) {
            steps += r.steps();
            bytes += r.bytes();
            engineBytes += r.engine().engineBytes();
            solverBytes += r.engine().solverBytes();
            stepNs += r.engine().stepNanos();
            collisionNs += r.engine().collisionNanos();
            solverNs += r.engine().solverNanos();
            wallSum += r.wallS();
            wall = Math.max(wall, r.wallS());
            // the workers' windows overlap: the longest one's steal is the pass's
            stolen = r.wallS() == wall ? r.stolenS() : stolen;
            cpu += r.cpuS();
            episodes += r.episodes();
            caught += r.loopsCaught();
            firstCatches += r.firstCatches();
            held &= r.held();
            ballToPalm = Math.max(ballToPalm, r.ballToPalm());
        }
        ObjectNode o = JsonNodeFactory.instance.objectNode();
        o.put("workers", runs.size());
        o.put("steps", steps);
        o.put("wall_s", wall);
        o.put("steps_per_s", steps / wall);
        o.put("realtime_factor", steps / wall * config.timeStep());
        o.put("steps_per_cpu_s", steps / cpu);
        if (Double.isFinite(stolen)) {
            o.put("host_steal_share", HostSteal.share(stolen, wall));
        }
        o.put("bytes_per_step", (double) bytes / steps);
        o.put("engine_bytes_per_step", (double) engineBytes / steps);
        o.put("solver_bytes_per_step", (double) solverBytes / steps);
        // where the wall time of the loop goes, timed inside the simulator's step()
        ObjectNode shares = o.putObject("time_shares");
        double wallNs = wallSum * 1e9;
        shares.put("solver", solverNs / wallNs);
        shares.put("collision", collisionNs / wallNs);
        shares.put("engine_glue", (stepNs - solverNs - collisionNs) / wallNs);
        shares.put("controller_pd_episode", Math.max(0, 1 - stepNs / wallNs));
        o.put("handsim_bytes_per_step", (double) (bytes - engineBytes) / steps);
        o.put("allocation_mb_per_s", bytes / wall / 1e6);
        o.put("episodes", episodes);
        o.put("loops_caught", caught);
        o.put("first_catches", firstCatches);
        o.put("ball_held", held);
        if (Double.isFinite(ballToPalm)) {
            o.put("ball_to_palm_m", ballToPalm);
        }
        return o;
    }

    static void print(String label, ObjectNode o) {
        System.out.printf("  %s: %d steps in %.2f s: %.0f steps/s, %.2fx real time (%.0f steps per CPU second), "
                + "%.0f bytes/step (engine %.0f, of which the constrained step %.0f; controller and loop %.0f); %d episodes, "
                + "%d catches%n", label, o.get("steps").asLong(),
                o.get("wall_s").asDouble(), o.get("steps_per_s").asDouble(), o.get("realtime_factor").asDouble(),
                o.get("steps_per_cpu_s").asDouble(), o.get("bytes_per_step").asDouble(), o.get("engine_bytes_per_step").asDouble(),
                o.get("solver_bytes_per_step").asDouble(), o.get("handsim_bytes_per_step").asDouble(), o.get("episodes").asInt(),
                o.get("loops_caught").asInt());
        if (o.has("host_steal_share")) {
            System.out.printf("    the host took %.1f %% of the CPUs' time (steal)%n", 100 * o.get("host_steal_share").asDouble());
        }
    }
}
