package handsim.math;

/**
 * The cubic Hermite curve of the paper's eq. (1):
 *
 * <pre>
 * p(s) = (2s^3 - 3s^2 + 1) p0 + dt (s^3 - 2s^2 + s) v0 + (-2s^3 + 3s^2) p1 + dt (s^3 - s^2) v1
 * </pre>
 *
 * with normalised time {@code s = (t - t0) / dt} in [0, 1] and {@code dt = t1 - t0}; velocities
 * are in world units per second, hence the factor {@code dt}. Outside [0, 1] the curve is held
 * at its end points.
 */
public record Hermite(Vec3 p0, Vec3 v0, Vec3 p1, Vec3 v1, double duration) {

    public Hermite {
        if (!(duration > 0)) {
            throw new IllegalArgumentException("Hermite duration must be > 0, got " + duration);
        }
    }

    /** Position at elapsed time {@code t} since the start of the curve. */
    public Vec3 position(double t) {
        if (t <= 0) {
            return p0;
        }
        if (t >= duration) {
            return p1;
        }
        double s = t / duration;
        double s2 = s * s;
        double s3 = s2 * s;
        double h00 = 2 * s3 - 3 * s2 + 1;
        double h10 = s3 - 2 * s2 + s;
        double h01 = -2 * s3 + 3 * s2;
        double h11 = s3 - s2;
        return p0.times(h00).plusScaled(v0, duration * h10).plusScaled(p1, h01).plusScaled(v1, duration * h11);
    }

    /** Velocity (d/dt of {@link #position}) at elapsed time {@code t}; zero outside the curve. */
    public Vec3 velocity(double t) {
        if (t < 0 || t > duration) {
            return Vec3.ZERO;
        }
        double s = t / duration;
        double s2 = s * s;
        double d00 = 6 * s2 - 6 * s;
        double d10 = 3 * s2 - 4 * s + 1;
        double d01 = -6 * s2 + 6 * s;
        double d11 = 3 * s2 - 2 * s;
        // dp/dt = (dp/ds) / dt; the dt factors of the velocity terms cancel
        return p0.times(d00 / duration).plusScaled(v0, d10).plusScaled(p1, d01 / duration).plusScaled(v1, d11);
    }
}
