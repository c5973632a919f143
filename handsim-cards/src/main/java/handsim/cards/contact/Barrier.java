package handsim.cards.contact;

/**
 * IPC's log barrier (Li et al. 2020, eq. 6): b(d) = −(d − d̂)² ln(d/d̂) for 0 < d < d̂, zero
 * beyond. handsim passes squared distances offset by the shell thickness ξ (Codim-IPC): the
 * argument is s = d² − ξ² and the activation ŝ = (ξ + d̂)² − ξ², so the barrier acts while the gap
 * d − ξ is below d̂ and grows without bound as the gap closes.
 */
public final class Barrier {

    private Barrier() {
    }

    public static double value(double d, double dhat) {
        if (d <= 0) {
            return Double.POSITIVE_INFINITY;
        }
        if (d >= dhat) {
            return 0;
        }
        double t = d - dhat;
        return -t * t * Math.log(d / dhat);
    }

    /** b'(d). */
    public static double slope(double d, double dhat) {
        if (d >= dhat || d <= 0) {
            return 0;
        }
        double t = d - dhat;
        return t * (-2 * Math.log(d / dhat) - t / d);
    }

    /** b''(d). */
    public static double curvature(double d, double dhat) {
        if (d >= dhat || d <= 0) {
            return 0;
        }
        double t = d - dhat;
        return -2 * Math.log(d / dhat) - 4 * t / d + t * t / (d * d);
    }
}
