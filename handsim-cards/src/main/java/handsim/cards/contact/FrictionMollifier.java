package handsim.cards.contact;

/**
 * IPC's smoothed friction (Li et al. 2020, sec. 5): f0 integrates f1, which ramps the friction
 * force from zero to full over tangential slips y below εv (f1(y) = 2y/εv − y²/εv², then 1).
 * With y a displacement over one step, εv is the slip-velocity threshold times the time step.
 */
public final class FrictionMollifier {

    private FrictionMollifier() {
    }

    public static double f0(double y, double epsV) {
        if (Math.abs(y) >= epsV) {
            return y;
        }
        return y * y * (1 - y / (3 * epsV)) / epsV + epsV / 3;
    }

    public static double f1(double y, double epsV) {
        if (Math.abs(y) >= epsV) {
            return 1;
        }
        double r = y / epsV;
        return r * (2 - r);
    }

    /** f1(y)/y, finite at y = 0. */
    public static double f1OverY(double y, double epsV) {
        if (Math.abs(y) >= epsV) {
            return 1 / y;
        }
        return (2 - y / epsV) / epsV;
    }

    /** f1'(y). */
    public static double f2(double y, double epsV) {
        if (Math.abs(y) >= epsV) {
            return 0;
        }
        return (2 - 2 * y / epsV) / epsV;
    }
}
