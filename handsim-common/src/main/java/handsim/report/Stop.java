package handsim.report;

import java.util.concurrent.atomic.AtomicInteger;

/**
 * A request to stop cleanly (SIGTERM, SIGINT or SIGHUP reached the process), seen by the long
 * loops that can end early without losing work: a demo writes the throws it made, an evaluation
 * keeps its finished episodes, training writes a checkpoint, a study records the trials that
 * finished. Such a loop runs inside {@link #watch()} and asks {@link #requested()} between units
 * of work (or calls {@link #check}, which throws {@link Stopped}). While nothing watches, a
 * signal ends the process at once, since no work is under way that a clean stop would keep.
 */
public final class Stop {

    /** Work that ended early because a stop was requested: exit status 128 + the signal's number. */
    public static final class Stopped extends RuntimeException {
        private static final long serialVersionUID = 1L;

        private final String signal;

        public Stopped(String signal, String whatWasKept) {
            super("stopped by " + signal + ": " + whatWasKept);
            this.signal = signal;
        }

        /** The signal that asked to stop ({@code SIGTERM}, ...). */
        public String signal() {
            return signal;
        }

        /** The exit status a process stopped by this signal ends with (the shell's 128 + its number). */
        public int status() {
            return Stop.status(signal);
        }
    }

    /** An open {@link #watch()}: closing it ends the watch. */
    public interface Watch extends AutoCloseable {
        @Override
        void close();
    }

    private static volatile String signal;
    private static final AtomicInteger WATCHERS = new AtomicInteger();

    private Stop() {
    }

    /** Asks the watching loops to stop; {@code signalName} says why ({@code SIGTERM}, {@code SIGINT}, {@code SIGHUP}). */
    public static void request(String signalName) {
        if (signal == null) {
            signal = signalName;
        }
    }

    /** Whether a stop was requested. */
    public static boolean requested() {
        return signal != null;
    }

    /** The signal that asked to stop, or null. */
    public static String signal() {
        return signal;
    }

    /** Forgets a request (a new command run in the same process, as tests do). */
    public static void reset() {
        signal = null;
    }

    /** Throws {@link Stopped}, saying {@code whatWasKept}, when a stop was requested. */
    public static void check(String whatWasKept) {
        String s = signal;
        if (s != null) {
            throw new Stopped(s, whatWasKept);
        }
    }

    /** Marks a loop that watches for a stop request, until the returned watch is closed. */
    public static Watch watch() {
        WATCHERS.incrementAndGet();
        return WATCHERS::decrementAndGet;
    }

    /** Whether a loop is watching: a signal then asks it to stop, rather than ending the process. */
    public static boolean watched() {
        return WATCHERS.get() > 0;
    }

    /** 128 + the signal's number, as a shell reports a process a signal ended: SIGTERM 143, SIGINT 130, SIGHUP 129. */
    public static int status(String signalName) {
        return switch (signalName) {
            case "SIGINT" -> 130;
            case "SIGHUP" -> 129;
            default -> 143;
        };
    }
}
