package handsim.scene;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;

/**
 * Runs an {@link InteractiveScene} in real time on a thread of its own and publishes what it
 * shows as {@link LiveFrame}s. Commands from other threads (scene commands, pause, speed, single
 * step) are queued and carried out on the run's thread between advances, so the scene is only
 * ever touched by that thread. A scene that throws is reported and the clock paused; the run
 * goes on.
 *
 * <p>Each pass ({@link #update}) adds the wall time elapsed to the {@link SimClock}, advances
 * the scene by what is owed (at most {@code maxChunkSeconds} at once, so that frames keep coming
 * while it catches up) once that is at least {@code minChunkSeconds}, and publishes a frame.
 */
public final class LiveRun implements AutoCloseable {

    /** Wall seconds over which the displayed real-time factor is measured. */
    static final double RATE_WINDOW = 0.5;
    /** The longest the run's thread sleeps between passes: commands wait at most this long. */
    private static final long MAX_PARK_NANOS = 2_000_000;

    private final InteractiveScene scene;
    private final SimClock clock;
    private final double minChunk;
    private final double maxChunk;
    private final Consumer<String> log;
    private final Queue<Consumer<InteractiveScene>> commands = new ConcurrentLinkedQueue<>();
    private final Queue<String> notes = new ConcurrentLinkedQueue<>();
    private volatile LiveFrame latest;
    private volatile boolean behind;
    private volatile boolean running;
    private Thread thread;
    private long sequence;
    // real-time factor: the window being measured, and totals since the start
    private double windowSim;
    private double windowWall;
    private double rate = Double.NaN;
    private volatile double totalSim;
    private volatile double totalWall;

    /** {@code log} receives every note (the app prints them); the run owns {@code scene}. */
    public LiveRun(InteractiveScene scene, SimClock clock, double minChunkSeconds, double maxChunkSeconds,
            Consumer<String> log) {
        if (!(minChunkSeconds > 0 && maxChunkSeconds >= minChunkSeconds)) {
            throw new IllegalArgumentException("chunks need 0 < min <= max, got " + minChunkSeconds + ", " + maxChunkSeconds);
        }
        this.scene = scene;
        this.clock = clock;
        this.minChunk = minChunkSeconds;
        this.maxChunk = maxChunkSeconds;
        this.log = log;
        publish();
    }

    /** Starts the run's thread; until then, {@link #update} may be called directly (tests). */
    public void start() {
        running = true;
        thread = new Thread(this::loop, "handsim-live");
        thread.setDaemon(true);
        thread.start();
    }

    private void loop() {
        long last = System.nanoTime();
        while (running) {
            long now = System.nanoTime();
            boolean advanced = update((now - last) / 1e9);
            last = now;
            if (!advanced) {
                // sleep until the next chunk is due (or a command may be waiting)
                double due = clock.wallSecondsUntilOwed(minChunk) * 1e9;
                LockSupport.parkNanos((long) Math.max(1, Math.min(MAX_PARK_NANOS, due)));
            }
        }
    }

    /**
     * One pass: carries out queued commands, adds {@code wallSeconds} to the clock, advances the
     * scene if enough is owed, and publishes a frame. Returns whether the scene advanced.
     */
    public boolean update(double wallSeconds) {
        boolean changed = false;
        for (Consumer<InteractiveScene> c; (c = commands.poll()) != null; changed = true) {
            try {
                c.accept(scene);
            } catch (RuntimeException e) {
                fail(e);
            }
        }
        double owed = clock.tick(wallSeconds);
        double advanced = 0;
        if (owed >= minChunk || owed > 0 && clock.isPaused()) {
            double before = scene.time();
            try {
                scene.advance(Math.min(owed, maxChunk));
                // a scene that restarted its episode has gone back in time: it advanced nothing
                advanced = Math.max(0, scene.time() - before);
            } catch (RuntimeException e) {
                fail(e);
            }
            clock.advanced(advanced);
            changed = true;
        }
        behind = clock.owed() > maxChunk;
        measure(wallSeconds, advanced);
        if (changed) {
            publish();
        }
        return advanced > 0;
    }

    private void measure(double wallSeconds, double simSeconds) {
        totalWall += wallSeconds;
        totalSim += simSeconds;
        windowWall += wallSeconds;
        windowSim += simSeconds;
        if (windowWall >= RATE_WINDOW) {
            rate = windowSim / windowWall;
            windowWall = 0;
            windowSim = 0;
        }
    }

    private void fail(RuntimeException e) {
        clock.setPaused(true);
        note("paused after an error in the scene: " + e);
    }

    private void note(String text) {
        notes.add(text);
        log.accept(text);
    }

    private void publish() {
        latest = new LiveFrame(scene.snapshot(), Collections.unmodifiableMap(new LinkedHashMap<>(scene.status())),
                scene.goal(), clock.speed(), clock.isPaused(), rate, sequence++);
    }

    /**
     * True while the scene owes more than one chunk of simulated time: it is not keeping up with
     * the wall clock, and a watcher drawing on the same cores should leave it room.
     */
    public boolean behind() {
        return behind;
    }

    /** The newest frame (never null). */
    public LiveFrame latest() {
        return latest;
    }

    /** Queues a scene command; its note arrives through {@link #pollNote()}. */
    public void command(SceneCommand command) {
        commands.add(s -> note(s.apply(command)));
    }

    public void setSpeed(double speed) {
        commands.add(s -> clock.setSpeed(speed));
    }

    public void setPaused(boolean paused) {
        commands.add(s -> clock.setPaused(paused));
    }

    /** Pauses and advances the scene by {@code simSeconds} (it moves in whole controller periods). */
    public void step(double simSeconds) {
        commands.add(s -> clock.requestStep(simSeconds));
    }

    /** The next note for the screen (results of commands, errors), or null. */
    public String pollNote() {
        return notes.poll();
    }

    /** Reports a note from outside the scene (e.g. the watcher's own), in the same stream. */
    public void report(String text) {
        note(text);
    }

    /** Simulated seconds advanced since the run was made. */
    public double simulatedSeconds() {
        return totalSim;
    }

    /** Wall seconds the run has measured since it was made. */
    public double wallSeconds() {
        return totalWall;
    }

    /** Stops the thread and closes the scene. */
    @Override
    public void close() {
        running = false;
        if (thread != null) {
            try {
                thread.join(5000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        scene.close();
    }
}
