package handsim.math;

/**
 * How a long object's axis turns end over end: about horizontal axes only. A can tossed end over
 * end turns about a horizontal axis and counts fully; one spun flat like a propeller turns about
 * the vertical and counts nothing (it never stands on its end). Used to count flips
 * ({@code task.FlightTracker}) and to let go of a throw at the right moment
 * ({@code control.ClosedLoopRelease}).
 */
public final class EndOverEnd {

    private EndOverEnd() {
    }

    /**
     * The end-over-end part of the long axis's turn from {@code from} to {@code to} (unit
     * vectors): the angle between them, weighted by how horizontal the axis they turn about is.
     */
    public static double turn(Vec3 from, Vec3 to, Vec3 up) {
        Vec3 turnAxis = from.cross(to);
        double sin = turnAxis.norm();
        if (sin < 1e-12) {
            return 0; // no turn, or exactly half a turn in one tick (no axis to tell)
        }
        return Math.atan2(sin, from.dot(to)) * horizontalPart(turnAxis, sin, up);
    }

    /**
     * The rate (rad/s) at which angular velocity {@code w} turns the unit axis {@code axis} end
     * over end, weighted as in {@link #turn}: the part of {@code w} square to the axis, as far as
     * it is horizontal. Spinning about the axis itself or about the vertical adds nothing.
     */
    public static double rate(Vec3 w, Vec3 axis, Vec3 up) {
        Vec3 square = axis.cross(w.cross(axis)); // w's part square to the axis: what turns the axis
        double rate = square.norm();
        return rate < 1e-12 ? 0 : rate * horizontalPart(square, rate, up);
    }

    /** How horizontal an axis of length {@code norm} is: 1 when square to {@code up} (unit), 0 along it. */
    private static double horizontalPart(Vec3 axis, double norm, Vec3 up) {
        double vertical = axis.dot(up) / norm;
        return Math.sqrt(Math.max(0, 1 - vertical * vertical));
    }
}
