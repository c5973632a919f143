package handsim.app;

import handsim.sim.Simulator;
import handsim.sim.StepAccounting;
import java.lang.management.ManagementFactory;

/** Wall time, this thread's CPU time and allocation of a bench worker from a start. */
final class BenchMeter {
    private static final com.sun.management.ThreadMXBean THREADS =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
    final Simulator sim;
    final long steps0;
    final StepAccounting engine0;
    final long t0;
    final long cpu0;
    final long bytes0;
    final double stolen0;

    /** Starts measuring, and counting the engine's own allocation apart. */
    BenchMeter(Simulator sim, long steps0) {
        this.sim = sim;
        this.steps0 = steps0;
        sim.setAccounting(true);
        engine0 = sim.accounting().copy();
        // read before the clocks and the allocation count start: /proc/stat's reading allocates
        stolen0 = HostSteal.seconds();
        t0 = System.nanoTime();
        cpu0 = THREADS.getCurrentThreadCpuTime();
        bytes0 = THREADS.getCurrentThreadAllocatedBytes();
    }

    BenchRun finish(long steps, int episodes, int caught, int firstCatches, boolean held, double ballToPalm) {
        double wallS = (System.nanoTime() - t0) / 1e9;
        double cpuS = (THREADS.getCurrentThreadCpuTime() - cpu0) / 1e9;
        long bytes = THREADS.getCurrentThreadAllocatedBytes() - bytes0;
        BenchRun r = new BenchRun(steps - steps0, wallS, cpuS, HostSteal.seconds() - stolen0, bytes, minus(sim.accounting(), engine0),
                episodes, caught, firstCatches, held, ballToPalm);
        sim.setAccounting(false);
        return r;
    }

    /** The accounting accumulated since {@code from}. */
    private static StepAccounting minus(StepAccounting now, StepAccounting from) {
        StepAccounting d = new StepAccounting();
        d.add(now.stepNanos() - from.stepNanos(), now.collisionNanos() - from.collisionNanos(),
                now.solverNanos() - from.solverNanos(), now.engineBytes() - from.engineBytes(),
                now.solverBytes() - from.solverBytes());
        return d;
    }
}
