package handsim.app;

import handsim.sim.StepAccounting;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.TimeUnit;

/** A {@code bench --compare} child process, spoken to line by line (see {@code BenchCommand.serveSlices}). */
final class SliceServer implements AutoCloseable {
    static final String READY = "ready", RUN = "run ", SLICE = "slice ", END = "end";
    private final Process process;
    private final BufferedReader from;
    private final PrintStream to;

    SliceServer(List<String> command) throws IOException {
        process = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.INHERIT).start();
        from = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
        to = new PrintStream(process.getOutputStream(), true, StandardCharsets.UTF_8);
    }

    void awaitReady() throws IOException {
        answer(READY);
    }

    BenchRun slice(long steps) throws IOException {
        to.println(RUN + steps);
        String[] f = answer(SLICE).substring(SLICE.length()).split(" ");
        StepAccounting engine = new StepAccounting();
        engine.add(Long.parseLong(f[5]), Long.parseLong(f[6]), Long.parseLong(f[7]), Long.parseLong(f[8]), Long.parseLong(f[9]));
        return new BenchRun(Long.parseLong(f[0]), Double.parseDouble(f[1]), Double.parseDouble(f[2]), Double.parseDouble(f[3]),
                Long.parseLong(f[4]), engine, 0, 0, 0, false, Double.NaN);
    }

    /** Episodes, catches and first catches since the warm-up. */
    int[] end() throws IOException {
        to.println(END);
        String[] f = answer(END).split(" ");
        return new int[] {Integer.parseInt(f[1]), Integer.parseInt(f[2]), Integer.parseInt(f[3])};
    }

    static String format(BenchRun r) {
        StepAccounting e = r.engine();
        return SLICE + r.steps() + " " + r.wallS() + " " + r.cpuS() + " " + r.stolenS() + " " + r.bytes() + " " + e.stepNanos() + " "
                + e.collisionNanos() + " " + e.solverNanos() + " " + e.engineBytes() + " " + e.solverBytes();
    }

    /** The child's next line starting with {@code prefix}, other lines skipped. */
    private String answer(String prefix) throws IOException {
        for (String line; (line = from.readLine()) != null; ) {
            if (line.startsWith(prefix)) {
                return line;
            }
        }
        throw new IllegalStateException("the bench's child process ended without answering (" + prefix.strip() + "): see its output above");
    }

    @Override
    public void close() {
        to.close();
        try {
            if (!process.waitFor(30, TimeUnit.SECONDS)) {
                process.destroyForcibly();
            }
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
        }
    }
}
