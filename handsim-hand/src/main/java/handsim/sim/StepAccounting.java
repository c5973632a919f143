package handsim.sim;

/**
 * What a simulator's {@link Simulator#step()} cost while accounting was on (see {@link
 * Simulator#setAccounting}): nanoseconds of wall time in the whole step, in collision and in the
 * solver, and the bytes the physics engine itself allocated (its solver arrays, its contact
 * joints), to tell them from the caller's. Totals since the simulator was made; take
 * differences. Mutable and owned by the simulator's thread.
 */
public final class StepAccounting {

    private long steps;
    private long stepNanos;
    private long collisionNanos;
    private long solverNanos;
    private long engineBytes;

    /** Adds one step's figures. */
    public void add(long step, long collision, long solver, long bytes) {
        steps++;
        stepNanos += step;
        collisionNanos += collision;
        solverNanos += solver;
        engineBytes += bytes;
    }

    public long steps() {
        return steps;
    }

    /** Wall time inside step(), ns. */
    public long stepNanos() {
        return stepNanos;
    }

    /** Of which contact generation, ns. */
    public long collisionNanos() {
        return collisionNanos;
    }

    /** Of which the engine's solver and integrator, ns. */
    public long solverNanos() {
        return solverNanos;
    }

    /** Bytes the engine allocated inside step(). */
    public long engineBytes() {
        return engineBytes;
    }

    /** An independent copy, to subtract later figures from. */
    public StepAccounting copy() {
        StepAccounting c = new StepAccounting();
        c.steps = steps;
        c.stepNanos = stepNanos;
        c.collisionNanos = collisionNanos;
        c.solverNanos = solverNanos;
        c.engineBytes = engineBytes;
        return c;
    }
}
