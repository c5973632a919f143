package handsim.control;

import handsim.config.Json;

/**
 * The documented range of every entry of the throw-parameter vector: the box the learner's
 * action in [-1, 1]^7 is mapped onto (tanh output scaled affinely, sec. 3.7).
 */
public record ThrowSpace(double[] low, double[] high) {

    public ThrowSpace {
        if (low.length != ThrowParameters.SIZE || high.length != ThrowParameters.SIZE) {
            throw new IllegalArgumentException("throw space bounds need " + ThrowParameters.SIZE + " entries");
        }
        for (int i = 0; i < low.length; i++) {
            if (!(low[i] < high[i])) {
                throw new IllegalArgumentException("throw space entry " + i + ": low " + low[i] + " must be < high " + high[i]);
            }
        }
        low = low.clone();
        high = high.clone();
    }

    public static ThrowSpace parse(Json j) {
        j.allow("comment");
        double[] dMin = j.numbers("dOffsetMin", 3), dMax = j.numbers("dOffsetMax", 3);
        double r = Math.toRadians(j.number("rTargetMaxDeg", 0, 180));
        double[] t = j.range("tOpen");
        j.requireNoUnknownFields();
        try {
            return new ThrowSpace(new double[] {dMin[0], dMin[1], dMin[2], -r, -r, -r, t[0]},
                    new double[] {dMax[0], dMax[1], dMax[2], r, r, r, t[1]});
        } catch (IllegalArgumentException e) {
            throw j.error(e.getMessage());
        }
    }

    /** Whether both boxes have the same bounds (a record of arrays compares them by identity). */
    public boolean sameBox(ThrowSpace other) {
        return java.util.Arrays.equals(low, other.low) && java.util.Arrays.equals(high, other.high);
    }

    @Override
    public String toString() {
        return "[" + java.util.Arrays.toString(low) + ", " + java.util.Arrays.toString(high) + "]";
    }

    /** Maps an action in [-1, 1]^7 (clipped) onto the box. */
    public ThrowParameters fromAction(double[] action) {
        double[] p = new double[ThrowParameters.SIZE];
        for (int i = 0; i < p.length; i++) {
            double a = Math.max(-1, Math.min(1, action[i]));
            p[i] = low[i] + 0.5 * (a + 1) * (high[i] - low[i]);
        }
        return ThrowParameters.fromArray(p);
    }

    /** The action in [-1, 1]^7 that maps onto {@code params} (clipped to the box). */
    public double[] toAction(ThrowParameters params) {
        double[] p = params.toArray();
        double[] a = new double[p.length];
        for (int i = 0; i < p.length; i++) {
            a[i] = Math.max(-1, Math.min(1, 2 * (p[i] - low[i]) / (high[i] - low[i]) - 1));
        }
        return a;
    }

    public boolean contains(ThrowParameters params) {
        double[] p = params.toArray();
        for (int i = 0; i < p.length; i++) {
            if (p[i] < low[i] - 1e-12 || p[i] > high[i] + 1e-12) {
                return false;
            }
        }
        return true;
    }
}
