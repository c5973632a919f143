package handsim.cards.sim;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.util.Arrays;

/**
 * Everything that changes while a card scene runs: time, step count, node positions and
 * velocities (3 per node, SI units), and the adaptive barrier stiffness with the last smallest
 * gap that drives it. Bone targets and lagged friction are functions of this state, so a
 * copy resumes a run bit for bit; {@link #write}/{@link #read} store it exactly.
 */
public final class SimState {

    private static final int MAGIC = 0x43415244; // "CARD"

    public double time;
    public long steps;
    public final double[] x;
    public final double[] v;
    public double kappa;
    public double kappaMax;
    public double previousMinGap2;

    public SimState(double[] x, double[] v) {
        this.x = x.clone();
        this.v = v.clone();
        this.previousMinGap2 = Double.POSITIVE_INFINITY;
    }

    public SimState copy() {
        SimState s = new SimState(x, v);
        s.time = time;
        s.steps = steps;
        s.kappa = kappa;
        s.kappaMax = kappaMax;
        s.previousMinGap2 = previousMinGap2;
        return s;
    }

    public int nodeCount() {
        return x.length / 3;
    }

    public void write(DataOutputStream out) throws IOException {
        out.writeInt(MAGIC);
        out.writeInt(x.length);
        out.writeDouble(time);
        out.writeLong(steps);
        out.writeDouble(kappa);
        out.writeDouble(kappaMax);
        out.writeDouble(previousMinGap2);
        for (double d : x) {
            out.writeDouble(d);
        }
        for (double d : v) {
            out.writeDouble(d);
        }
    }

    public static SimState read(DataInputStream in) throws IOException {
        if (in.readInt() != MAGIC) {
            throw new IOException("not a card-scene checkpoint");
        }
        int n = in.readInt();
        double time = in.readDouble();
        long steps = in.readLong();
        double kappa = in.readDouble();
        double kappaMax = in.readDouble();
        double prev = in.readDouble();
        double[] x = new double[n];
        double[] v = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = in.readDouble();
        }
        for (int i = 0; i < n; i++) {
            v[i] = in.readDouble();
        }
        SimState s = new SimState(x, v);
        s.time = time;
        s.steps = steps;
        s.kappa = kappa;
        s.kappaMax = kappaMax;
        s.previousMinGap2 = prev;
        return s;
    }

    /** Equal bit for bit (positions, velocities, time, steps, barrier state). */
    public boolean sameAs(SimState o) {
        return Double.doubleToRawLongBits(time) == Double.doubleToRawLongBits(o.time) && steps == o.steps
                && Double.doubleToRawLongBits(kappa) == Double.doubleToRawLongBits(o.kappa)
                && Double.doubleToRawLongBits(previousMinGap2) == Double.doubleToRawLongBits(o.previousMinGap2)
                && Arrays.equals(x, o.x) && Arrays.equals(v, o.v);
    }
}
