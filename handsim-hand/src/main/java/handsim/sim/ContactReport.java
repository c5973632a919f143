package handsim.sim;

/**
 * Hand-object contacts of the last physics step: which bodies touched (a bit per body index,
 * the model has fewer than 64 bodies), how many contact points, and the deepest penetration.
 * A mutable record reused every step; copy what you keep.
 */
public final class ContactReport {

    private long bodyMask;
    private int points;
    private double maxDepth;
    private double time;

    /** Clears the report at the start of a step taken at time {@code t}. */
    public void clear(double t) {
        bodyMask = 0;
        points = 0;
        maxDepth = 0;
        time = t;
    }

    /** Records one contact point between body {@code body} and the object. */
    public void add(int body, double depth) {
        bodyMask |= 1L << body;
        points++;
        maxDepth = Math.max(maxDepth, depth);
    }

    public boolean any() {
        return points > 0;
    }

    public boolean touches(int body) {
        return (bodyMask & (1L << body)) != 0;
    }

    public long bodyMask() {
        return bodyMask;
    }

    public int points() {
        return points;
    }

    /** Deepest palm/finger-object penetration of the step, metres. */
    public double maxDepth() {
        return maxDepth;
    }

    /** Simulated time of the step these contacts belong to. */
    public double time() {
        return time;
    }

    public int bodyCount() {
        return Long.bitCount(bodyMask);
    }
}
