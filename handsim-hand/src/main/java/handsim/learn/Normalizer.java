package handsim.learn;

/**
 * Running per-dimension mean and variance of the observations (Welford's algorithm), used to
 * standardise the networks' inputs: {@code clip((x - mean) / max(std, minStd), -clip, clip)}.
 * When disabled it passes observations through unchanged. Not thread-safe; {@link Policy}
 * carries a frozen copy.
 */
public final class Normalizer {

    private final boolean enabled;
    private final double clip;
    private final double minStd;
    private final double[] mean;
    private final double[] m2;
    private long count;

    public Normalizer(int size, boolean enabled, double clip, double minStd) {
        this.enabled = enabled;
        this.clip = clip;
        this.minStd = minStd;
        this.mean = new double[size];
        this.m2 = new double[size];
    }

    public int size() {
        return mean.length;
    }

    public boolean enabled() {
        return enabled;
    }

    public double clip() {
        return clip;
    }

    public long count() {
        return count;
    }

    /** Adds one observation to the statistics. */
    public void observe(double[] x) {
        if (x.length != mean.length) {
            throw new IllegalArgumentException("observation has " + x.length + " entries, expected " + mean.length);
        }
        count++;
        for (int i = 0; i < x.length; i++) {
            double d = x[i] - mean[i];
            mean[i] += d / count;
            m2[i] += d * (x[i] - mean[i]);
        }
    }

    /** The current means (identity normaliser: zeros). */
    public double[] mean() {
        return enabled ? mean.clone() : new double[mean.length];
    }

    /** The current standard deviations, floored at minStd (identity normaliser: ones). */
    public double[] std() {
        double[] s = new double[mean.length];
        for (int i = 0; i < s.length; i++) {
            s[i] = enabled ? Math.max(minStd, count > 1 ? Math.sqrt(m2[i] / count) : 0) : 1;
        }
        return s;
    }

    /** Writes the normalised rows of {@code x} (row-major, rows of size()) into {@code out}. */
    public void normalize(double[] x, double[] out) {
        if (!enabled) {
            System.arraycopy(x, 0, out, 0, x.length);
            return;
        }
        double[] std = std();
        int n = mean.length;
        for (int k = 0; k < x.length; k++) {
            int i = k % n;
            out[k] = clip((x[k] - mean[i]) / std[i], clip);
        }
    }

    public double[] normalize(double[] x) {
        double[] out = new double[x.length];
        normalize(x, out);
        return out;
    }

    static double clip(double v, double c) {
        return Math.max(-c, Math.min(c, v));
    }

    // ---- checkpoint state -----------------------------------------------------------------

    double[] rawMean() {
        return mean.clone();
    }

    double[] rawM2() {
        return m2.clone();
    }

    void restore(double[] savedMean, double[] savedM2, long savedCount) {
        if (savedMean.length != mean.length || savedM2.length != m2.length) {
            throw new IllegalArgumentException("normaliser state of size " + savedMean.length + ", expected " + mean.length);
        }
        System.arraycopy(savedMean, 0, mean, 0, mean.length);
        System.arraycopy(savedM2, 0, m2, 0, m2.length);
        count = savedCount;
    }
}
