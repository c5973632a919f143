package handsim.sim;

/**
 * What a simulator's {@link Simulator#step()} cost while accounting was on (see {@link
 * Simulator#setAccounting}): nanoseconds of wall time in the whole step, in collision and in the
 * solver, and the bytes the physics engine itself allocated (its solver arrays, its contact
 * joints, its colliders), to tell them from the caller's, and of those the solver's alone. Totals since the simulator was made; take
 * differences. Mutable and owned by the simulator's thread.
 */
public final class StepAccounting {

    private long steps;
    private long stepNanos;
    private long collisionNanos;
    private long solverNanos;
    private long engineBytes;
    private long solverBytes;

    /** Adds one step's figures: nanoseconds in the step, collision and solver; bytes of the engine and of its solver. */
    public void add(long step, long collision, long solver, long bytes, long solverOnlyBytes) {
        steps++;
        stepNanos += step;
        collisionNanos += collision;
        solverNanos += solver;
        engineBytes += bytes;
        solverBytes += solverOnlyBytes;
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

    /** Of which the solver and integrator allocated (the constrained step alone). */
    public long solverBytes() {
        return solverBytes;
    }

    /** An independent copy, to subtract later figures from. */
    public StepAccounting copy() {
        StepAccounting c = new StepAccounting();
        c.steps = steps;
        c.stepNanos = stepNanos;
        c.collisionNanos = collisionNanos;
        c.solverNanos = solverNanos;
        c.engineBytes = engineBytes;
        c.solverBytes = solverBytes;
        return c;
    }
}
