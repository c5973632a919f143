package handsim.control;

import handsim.math.Vec3;

/**
 * Free flight under constant gravity (air damping is small enough to ignore over a throw:
 * 0.01/s changes the velocity by under 1 % per second).
 */
public record Ballistics(Vec3 gravity) {

    public Vec3 position(Vec3 p0, Vec3 v0, double t) {
        return p0.plus(v0.times(t)).plus(gravity.times(0.5 * t * t));
    }

    public Vec3 velocity(Vec3 v0, double t) {
        return v0.plus(gravity.times(t));
    }

    /**
     * Time at which a body at height {@code p0.y} with vertical velocity {@code v0.y} next
     * crosses height {@code y} while descending; NaN if it never comes down to that height
     * (gravity must point down, -y).
     */
    public double descendingCrossing(Vec3 p0, Vec3 v0, double y) {
        double g = -gravity.y();
        // y(t) = p0.y + v0.y t - g t^2 / 2 = y  ->  g/2 t^2 - v0.y t + (y - p0.y) = 0, larger root
        double disc = v0.y() * v0.y() + 2 * g * (p0.y() - y);
        if (disc < 0 || g <= 0) {
            return Double.NaN;
        }
        double t = (v0.y() + Math.sqrt(disc)) / g;
        return t >= 0 ? t : Double.NaN;
    }

    /** Highest point reached from the current state (the current height if already descending). */
    public double apexHeight(Vec3 p0, Vec3 v0) {
        double g = -gravity.y();
        return v0.y() > 0 ? p0.y() + v0.y() * v0.y() / (2 * g) : p0.y();
    }
}
