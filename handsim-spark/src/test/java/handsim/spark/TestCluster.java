package handsim.spark;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A standalone cluster on this machine for a test: {@code scripts/spark-cluster start} with a
 * master on a free port and N workers of one core, in a folder of its own; {@link #close} stops
 * it, and a JVM shutdown hook does if the test never gets there, so no test leaves a process
 * behind.
 */
final class TestCluster implements AutoCloseable {

    private static final Path SCRIPT = Path.of("scripts/spark-cluster").toAbsolutePath();

    private final Path dir;
    private final String master;
    private final Thread stopAtExit;
    private boolean stopped;

    private TestCluster(Path dir, String master) {
        this.dir = dir;
        this.master = master;
        this.stopAtExit = new Thread(this::stop, "stop-test-cluster");
        Runtime.getRuntime().addShutdownHook(stopAtExit);
    }

    static TestCluster start(int workers) throws IOException, InterruptedException {
        Path dir = Files.createTempDirectory("handsim-cluster");
        int port;
        try (ServerSocket s = new ServerSocket(0)) {
            port = s.getLocalPort();
        }
        Process p = new ProcessBuilder(SCRIPT.toString(), "start", "--workers", Integer.toString(workers), "--port", Integer.toString(port),
                "--dir", dir.toString()).redirectError(ProcessBuilder.Redirect.INHERIT).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        if (!p.waitFor(5, TimeUnit.MINUTES) || p.exitValue() != 0) {
            run("stop", dir); // whatever it started before it failed
            throw new IllegalStateException("scripts/spark-cluster start failed (exit " + p.exitValue() + "): " + out);
        }
        return new TestCluster(dir, out.lines().reduce((a, b) -> b).orElseThrow());
    }

    String master() {
        return master;
    }

    /** Kills worker {@code i} (1-based) and its executors at once, as a machine lost would: SIGKILL, no shutdown. */
    void killWorker(int i) throws IOException {
        long pid = Long.parseLong(Files.readString(dir.resolve("worker-" + i + ".pid")).trim());
        ProcessHandle worker = ProcessHandle.of(pid).orElseThrow(() -> new IllegalStateException("worker " + i + " is not running"));
        List<ProcessHandle> all = new java.util.ArrayList<>(worker.descendants().toList());
        all.add(worker);
        all.forEach(ProcessHandle::destroyForcibly);
    }

    private synchronized void stop() {
        if (!stopped) {
            stopped = true;
            try {
                run("stop", dir);
            } catch (IOException | InterruptedException e) {
                throw new IllegalStateException("scripts/spark-cluster stop failed for " + dir, e);
            }
        }
    }

    private static void run(String action, Path dir) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(SCRIPT.toString(), action, "--dir", dir.toString()).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        p.waitFor(2, TimeUnit.MINUTES);
    }

    @Override
    public void close() {
        stop();
        try {
            Runtime.getRuntime().removeShutdownHook(stopAtExit);
        } catch (IllegalStateException exiting) {
            // the JVM is shutting down: the hook runs or ran
        }
    }

    /** Fails with the path if it cannot be read (for the messages of tests). */
    static String read(Path f) {
        try {
            return Files.readString(f);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
