package handsim.math;

/**
 * How a long object's axis turns end over end: about horizontal axes only. A can tossed end over
 * end turns about a horizontal axis and counts fully; one spun flat like a propeller turns about
 * the vertical and counts nothing (it never stands on its end), and an axis that wobbles, tilted
 * out of the horizontal and swept round the vertical, turns about horizontal axes that keep
 * changing direction and so adds up to little. Used to count flips ({@code task.FlightTracker})
 * and to let go of a throw at the right moment ({@code control.ClosedLoopRelease}).
 */
public final class EndOverEnd {

    private EndOverEnd() {
    }

    /**
     * The rotation vector (axis times angle, rad) of the shortest turn that carries the unit
     * vector {@code from} to the unit vector {@code to}: one tick of a long axis's turn. Summed
     * over a flight, turns back and forth cancel.
     */
    public static Vec3 step(Vec3 from, Vec3 to) {
        Vec3 turnAxis = from.cross(to);
        double sin = turnAxis.norm();
        if (sin < 1e-12) {
            return Vec3.ZERO; // no turn, or exactly half a turn in one tick (no axis to tell)
        }
        return turnAxis.times(Math.atan2(sin, from.dot(to)) / sin);
    }

    /**
     * The net end-over-end turn (rad) of a summed rotation vector {@code turn}: the length of its
     * horizontal part, the turn about one fixed horizontal axis. Turning about the vertical (a
     * flat spin) adds nothing, nor does a wobble, whose horizontal turn axis sweeps round and
     * cancels itself: an axis at elevation e swept round the vertical sums to at most sin 2e.
     */
    public static double net(Vec3 turn, Vec3 up) {
        return turn.minus(up.times(turn.dot(up))).norm();
    }

    /**
     * The rate (rad/s) at which angular velocity {@code w} turns the unit axis {@code axis} end
     * over end: the part of {@code w} square to the axis, as far as it is horizontal. Spinning
     * about the axis itself or about the vertical adds nothing.
     */
    public static double rate(Vec3 w, Vec3 axis, Vec3 up) {
        Vec3 square = axis.cross(w.cross(axis)); // w's part square to the axis: what turns the axis
        double rate = square.norm();
        if (rate < 1e-12) {
            return 0;
        }
        double vertical = square.dot(up) / rate;
        return rate * Math.sqrt(Math.max(0, 1 - vertical * vertical));
    }
}
