package handsim.scene;

/**
 * The sim-time accumulator that paces a scene to the wall clock. Every poll adds the wall time
 * that passed, times the speed (1 real time, 0.5 half speed, ...), to the simulated time owed;
 * the scene is then advanced by what is owed and reports what it really advanced (scenes move in
 * whole controller periods, so the overshoot is carried as a small negative debt). The simulation
 * is driven by elapsed time, never by the number of frames drawn.
 *
 * <p>The debt is capped at {@code maxLagSeconds}: when the simulation cannot keep up, it falls
 * behind real time (the measured real-time factor shows it and {@link #droppedSeconds()} counts
 * the time given up) instead of trying ever larger catch-ups (the "spiral of death").
 */
public final class SimClock {

    private final double maxLag;
    private double speed = 1;
    private boolean paused;
    private double owed;
    private double stepOwed;
    private double dropped;

    public SimClock(double maxLagSeconds) {
        if (!(maxLagSeconds > 0)) {
            throw new IllegalArgumentException("maxLagSeconds must be > 0, got " + maxLagSeconds);
        }
        this.maxLag = maxLagSeconds;
    }

    /** Simulated seconds per wall second while running (> 0). */
    public void setSpeed(double s) {
        if (!(s > 0 && s <= 100)) {
            throw new IllegalArgumentException("speed must be in (0, 100], got " + s);
        }
        speed = s;
    }

    public double speed() {
        return speed;
    }

    /** Pausing forgets what was owed, so that resuming does not jump. */
    public void setPaused(boolean p) {
        paused = p;
        owed = 0;
    }

    public boolean isPaused() {
        return paused;
    }

    /** Pauses and owes {@code simSeconds} more: the scene advances by that much and stops again. */
    public void requestStep(double simSeconds) {
        if (!(simSeconds > 0)) {
            throw new IllegalArgumentException("a single step must be > 0 s, got " + simSeconds);
        }
        setPaused(true);
        stepOwed += simSeconds;
    }

    /** Adds {@code wallSeconds} of elapsed wall time and returns the simulated seconds owed now. */
    public double tick(double wallSeconds) {
        if (!(wallSeconds >= 0)) {
            throw new IllegalArgumentException("wall time must be >= 0, got " + wallSeconds);
        }
        if (!paused) {
            owed += wallSeconds * speed;
            if (owed > maxLag) {
                dropped += owed - maxLag;
                owed = maxLag;
            }
        }
        return owed();
    }

    /** Simulated seconds owed (single steps included). */
    public double owed() {
        return Math.max(0, owed) + stepOwed;
    }

    /** The scene advanced by {@code simSeconds}: pays single steps first, then the running debt. */
    public void advanced(double simSeconds) {
        double forSteps = Math.min(stepOwed, simSeconds);
        stepOwed -= forSteps;
        if (!paused) {
            owed -= simSeconds - forSteps;
        }
    }

    /** Wall seconds until {@code simSeconds} will be owed (infinite while paused). */
    public double wallSecondsUntilOwed(double simSeconds) {
        if (owed() >= simSeconds) {
            return 0;
        }
        return paused ? Double.POSITIVE_INFINITY : (simSeconds - owed()) / speed;
    }

    /** Simulated seconds given up to the lag cap since the clock was made. */
    public double droppedSeconds() {
        return dropped;
    }
}
