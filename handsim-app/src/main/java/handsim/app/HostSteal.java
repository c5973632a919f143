package handsim.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The CPU time a hypervisor took from this machine's CPUs (Linux's "steal" in /proc/stat): on a
 * virtual machine it slows every run by an amount that comes and goes, so a benchmark reports it
 * beside its rates.
 */
final class HostSteal {

    /** /proc/stat counts in USER_HZ ticks, 100 a second on Linux's mainstream architectures. */
    private static final double TICKS_PER_S = 100;
    private static final Path STAT = Path.of("/proc/stat");

    private HostSteal() {
    }

    /** All CPUs' stolen time so far in seconds, NaN where /proc/stat does not say. */
    static double seconds() {
        try {
            for (String line : Files.readAllLines(STAT)) {
                if (line.startsWith("cpu ")) {
                    // cpu user nice system idle iowait irq softirq steal ...
                    String[] f = line.trim().split("\\s+");
                    return f.length > 8 ? Long.parseLong(f[8]) / TICKS_PER_S : Double.NaN;
                }
            }
        } catch (IOException | RuntimeException e) {
            return Double.NaN;
        }
        return Double.NaN;
    }

    /** The share of the machine's CPU time stolen over {@code wallS} seconds in which {@code stolenS} were. */
    static double share(double stolenS, double wallS) {
        return stolenS / (wallS * Runtime.getRuntime().availableProcessors());
    }
}
