package handsim.app;

import handsim.report.Stop;
import java.util.List;
import sun.misc.Signal;

/**
 * SIGTERM, SIGINT (Ctrl-C) and SIGHUP as requests to stop cleanly ({@link Stop}): while a long
 * loop watches for one (a demo, an evaluation, training, a study), it ends after saving what it
 * did; otherwise the process ends at once. The same signal again, a second or more later, ends
 * the process at once; within that second it is the same request delivered twice (Ctrl-C reaches
 * the launcher, which passes it on, and the JVM, in the same process group). A JVM started by
 * the launcher for a supervised run also stops when the launcher itself ends
 * ({@code -Dhandsim.launcherPid}), say killed with SIGKILL.
 */
final class Signals {

    /** The launcher's process, which a supervised JVM outlives only to stop cleanly. */
    static final String LAUNCHER_PID_PROPERTY = "handsim.launcherPid";
    /** A second signal within this time of the first (ns) is the same one delivered twice. */
    private static final long SAME_REQUEST_NANOS = 1_000_000_000L;

    private static volatile long firstAt;

    private Signals() {
    }

    /** Installs the handlers (in a process of its own only: never in a test's JVM). */
    static void install() {
        for (String name : List.of("TERM", "INT", "HUP")) {
            try {
                Signal.handle(new Signal(name), s -> received("SIG" + s.getName()));
            } catch (IllegalArgumentException ignoredOrReserved) {
                // a signal this process ignores (nohup) or the JVM keeps for itself: left as it is
            }
        }
        String launcher = System.getProperty(LAUNCHER_PID_PROPERTY);
        if (launcher != null && launcher.matches("\\d+")) {
            ProcessHandle.of(Long.parseLong(launcher)).ifPresent(h -> h.onExit().thenRun(() -> received("SIGHUP")));
        }
    }

    private static synchronized void received(String signal) {
        long now = System.nanoTime();
        if (Stop.requested()) {
            if (now - firstAt > SAME_REQUEST_NANOS) {
                exitNow(signal);
            }
            return;
        }
        if (!Stop.watched()) {
            exitNow(signal);
            return;
        }
        firstAt = now;
        Stop.request(signal);
        System.out.println("handsim: " + signal + ": stopping once the work under way is saved (" + signal
                + " again, a second from now or later, stops at once)");
    }

    /** Ends the process with the shell's status for the signal; the exit hooks delete temporary files and release locks. */
    private static void exitNow(String signal) {
        new Thread(() -> System.exit(Stop.status(signal)), "handsim-exit").start();
    }
}
