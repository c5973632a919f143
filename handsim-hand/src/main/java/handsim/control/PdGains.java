package handsim.control;

import handsim.config.Json;

/**
 * The PD gain law of eq. (4): {@code kp = wp m^2 + kbase}, {@code kd = wd m}, with m the mass
 * driven by the joint. The paper uses wp = 500, wd = 0.2, kbase = 0.1 for everything.
 */
public record PdGains(double wp, double wd, double kbase) {

    public static PdGains parse(Json j) {
        j.allow("comment");
        PdGains g = new PdGains(j.number("wp", 0, 1e9), j.number("wd", 0, 1e9), j.number("kbase", 0, 1e9));
        j.requireNoUnknownFields();
        return g;
    }

    /** Stiffness (N m/rad) for a joint driving {@code mass} kg. */
    public double kp(double mass) {
        return wp * mass * mass + kbase;
    }

    /** Damping (N m s/rad) for a joint driving {@code mass} kg. */
    public double kd(double mass) {
        return wd * mass;
    }
}
