package handsim.sim.island;

/**
 * The generator of the solver's random row order, one per world: ODE's 32-bit linear
 * congruential sequence (seed' = 1664525 seed + 1013904223 mod 2^32, Numerical Recipes' constants)
 * and its integer mapping, which xor-folds the high bits into the low ones before scaling to
 * [0, n). Seeded like ode4j's process-wide generator, a world draws the same sequence ode4j would
 * draw for it alone.
 */
final class ShuffleRandom {

    private static final long MULTIPLIER = 1664525L;
    private static final long INCREMENT = 1013904223L;
    private static final long MASK = 0xffffffffL;

    private long seed;

    void setSeed(long seed) {
        this.seed = seed;
    }

    long seed() {
        return seed;
    }

    /** The next 32-bit value. */
    long next() {
        seed = (MULTIPLIER * seed + INCREMENT) & MASK;
        return seed;
    }

    /** An integer in [0, n), 1 <= n < 2^31. */
    int below(int n) {
        long r = next();
        if (n <= 16) {
            r ^= r >> 16;
            r ^= r >> 8;
            r ^= r >> 4;
            if (n <= 2) {
                r ^= r >> 2;
                r ^= r >> 1;
                return (int) (r & (n >> 1));
            }
            if (n <= 4) {
                r ^= r >> 2;
                return (int) (((r & 0x3L) * n) >> 2);
            }
            return (int) (((r & 0xfL) * n) >> 4);
        }
        if (n <= 256) {
            r ^= r >> 16;
            r ^= r >> 8;
            return (int) (((r & 0xffL) * n) >> 8);
        }
        if (n <= 65536) {
            r ^= r >> 16;
            return (int) (((r & 0xffffL) * n) >> 16);
        }
        return (int) ((r * n) >> 32);
    }
}
