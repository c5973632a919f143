package handsim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The bench command on a tiny budget: the JSON fields, consistent with each other. */
@Tag("slow")
class BenchCommandTest {

    @Test
    void twoWorkerLoopBenchWritesThroughputSpeedupAndAllocation(@TempDir Path dir) throws Exception {
        Path json = dir.resolve("bench.json");
        // 0.12 s of loops per worker: long enough for every figure, too short for a catch (a launch
        // reaches the interception plane after 0.55-0.85 s, configs/launch.json), so bench exits 1
        int code = Main.run("bench", "--seconds", "0.1", "--warmup", "0.02", "--workers", "2", "--json", json.toString());
        JsonNode out = new ObjectMapper().readTree(json.toFile());
        assertEquals(0, out.get("single_worker").get("loops_caught").asInt(), out.toString());
        assertEquals(1, code, "no catch in 0.12 s: bench says the loop did not run as a loop");
        assertEquals(2, out.get("workers").asInt());
        double h = out.get("time_step_s").asDouble();
        JsonNode single = out.get("single_worker");
        JsonNode parallel = out.get("parallel");
        // each worker measures exactly its simulated time
        assertEquals(500, single.get("steps").asLong());
        assertEquals(1000, parallel.get("steps").asLong());
        assertEquals(parallel.get("steps_per_s").asDouble(), out.get("steps_per_s").asDouble(), 0.0);
        assertEquals(out.get("steps_per_s").asDouble() * h, out.get("realtime_factor").asDouble(), 1e-9);
        assertEquals(out.get("steps_per_s").asDouble() / single.get("steps_per_s").asDouble(), out.get("speedup").asDouble(), 1e-9);
        assertTrue(out.get("bytes_per_step").asDouble() > 0);
        assertEquals(single.get("bytes_per_step").asDouble(),
                single.get("engine_bytes_per_step").asDouble() + single.get("handsim_bytes_per_step").asDouble(), 1e-6);
        // solver, collision, engine glue (timed inside step()) and the rest of the loop
        double shares = 0;
        for (var it = single.get("time_shares").elements(); it.hasNext(); ) {
            double share = it.next().asDouble();
            assertTrue(share >= 0 && share <= 1, "share " + share);
            shares += share;
        }
        assertEquals(1.0, shares, 1e-9, "time shares add up");
        assertTrue(single.get("time_shares").get("solver").asDouble() > 0.3, "the solver dominates the step");
        assertTrue(single.has("sampled_shares"));
        // which code and command the figures are of
        JsonNode provenance = out.get("provenance");
        assertTrue(provenance.get("command").asText().startsWith("scripts/handsim bench --seconds 0.1"), provenance.toString());
        assertTrue(provenance.get("commit").asText().length() > 0, provenance.toString());
        assertTrue(provenance.get("files").has("configs/sim.json"), provenance.toString());
        if (java.nio.file.Files.isReadable(java.nio.file.Path.of("/proc/stat"))) {
            // the hypervisor's share of the CPUs during the measured window: a fraction
            for (JsonNode pass : new JsonNode[] {single, parallel}) {
                double steal = pass.get("host_steal_share").asDouble();
                assertTrue(steal >= 0 && steal <= 1, "host_steal_share " + steal);
            }
        }
    }

    @Test
    void handsimsStepAllocatesNothingAndTheHeldBallLoopAlmostNothing(@TempDir Path dir) throws Exception {
        Path json = dir.resolve("bench.json");
        // 10 s of warm-up (50,000 steps): long enough for the JIT to compile ode4j's colliders,
        // whose temporaries escape analysis then removes; 1 s measured with the ball held
        int code = Main.run("bench", "--scenario", "held-ball", "--stepper", "handsim", "--warmup", "10", "--seconds", "1",
                "--json", json.toString());
        JsonNode out = new ObjectMapper().readTree(json.toFile());
        assertEquals(0, code, "the ball is held");
        assertEquals("handsim", out.get("stepper").asText());
        JsonNode single = out.get("single_worker");
        // the step's arrays are allocated once: nothing per step
        assertEquals(0.0, single.get("solver_bytes_per_step").asDouble(), 0.0, out.toString());
        // the bound is 1 KB a step; the held ball's loop (servo, contacts, colliders) allocates
        // nothing once compiled, 64 bytes leave room for a stray allocation of the JIT's
        assertTrue(out.get("bytes_per_step").asDouble() <= 64, out.toString());
    }

    @Test
    void badArgumentsExitWithStatus2() {
        assertEquals(2, Main.run("bench", "--workers", "0"));
        assertEquals(2, Main.run("bench", "--scenario", "juggle"));
        assertEquals(2, Main.run("bench", "--stepper", "bullet"));
        assertEquals(2, Main.run("bench", "--compare", "--workers", "2"));
        assertEquals(2, Main.run("bench", "--compare", "--stepper", "ode4j"));
        assertEquals(2, Main.run("bench", "--compare", "--seconds", "1", "--slice", "2"));
    }

    @Test
    void compareAlternatesBothSteppersAndReportsTheirRatio(@TempDir Path dir) throws Exception {
        Path json = dir.resolve("compare.json");
        // 0.1 s per stepper in slices of 0.04 s: rounds of 200, 200 and 100 steps; no catch in that time
        int code = Main.run("bench", "--compare", "--seconds", "0.1", "--warmup", "0.02", "--slice", "0.04", "--json", json.toString());
        assertEquals(1, code, "no catch in 0.12 s");
        // each stepper ran in a JVM of its own, and neither outlives the command
        assertEquals(0, ProcessHandle.current().children()
                .filter(p -> p.isAlive() && p.info().commandLine().map(c -> c.contains("--serve-slices")).orElse(false)).count(),
                "child JVMs left running");
        JsonNode out = new ObjectMapper().readTree(json.toFile());
        assertEquals(3, out.get("rounds").asInt());
        JsonNode handsim = out.get("handsim");
        JsonNode ode4j = out.get("ode4j");
        // each world measures exactly its simulated time, summed over its slices
        assertEquals(500, handsim.get("steps").asLong());
        assertEquals(500, ode4j.get("steps").asLong());
        assertEquals(handsim.get("steps_per_s").asDouble() / ode4j.get("steps_per_s").asDouble(), out.get("ratio_steps_per_s").asDouble(),
                1e-12);
        // each world ran its own stepper: quickStep allocates tens of KB a step (docs/design.md),
        // handsim's step nothing once compiled (here still cold: under the 1 KB)
        assertTrue(handsim.get("solver_bytes_per_step").asDouble() < 1000, out.toString());
        assertTrue(ode4j.get("solver_bytes_per_step").asDouble() > 10_000, out.toString());
        JsonNode rounds = out.get("round_ratios");
        double min = rounds.get("min").asDouble(), max = rounds.get("max").asDouble();
        for (String q : new String[] {"q1", "median", "q3"}) {
            double v = rounds.get(q).asDouble();
            assertTrue(v >= min && v <= max && min > 0, q + " " + v + " outside [" + min + ", " + max + "]");
        }
    }
}
