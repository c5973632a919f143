package handsim.control;

import handsim.kin.Frame;
import handsim.math.Hermite;
import handsim.math.Quat;
import handsim.math.Vec3;

/**
 * The palm target of one FSM state: position along the Hermite curve of eq. (1), rotation by
 * SLERP from the state's start rotation to its end rotation (sec. 3.1-3.2), both over the
 * state's duration.
 */
public record PalmTrajectory(Hermite path, Quat startRotation, Quat endRotation) {

    public double duration() {
        return path.duration();
    }

    /** Target palm frame {@code t} seconds after the state began. */
    public Frame at(double t) {
        double s = Math.max(0, Math.min(1, t / path.duration()));
        return new Frame(path.position(t), startRotation.slerp(endRotation, s));
    }

    /**
     * As {@link #at}, and past the duration the palm goes on at the curve's end velocity,
     * turning on at the state's average rate (a THROW held open by a {@link ClosedLoopRelease}).
     */
    public Frame continuedAt(double t) {
        double over = t - path.duration();
        if (over <= 0) {
            return at(t);
        }
        Vec3 turn = endRotation.mul(startRotation.conjugate()).toRotationVector();
        return new Frame(path.p1().plus(path.v1().times(over)),
                Quat.fromRotationVector(turn.times(over / path.duration())).mul(endRotation));
    }

    public Vec3 velocity(double t) {
        return path.velocity(t);
    }

    /** A trajectory that holds a frame still. */
    public static PalmTrajectory hold(Frame f, double duration) {
        return new PalmTrajectory(new Hermite(f.origin(), Vec3.ZERO, f.origin(), Vec3.ZERO, duration), f.rotation(),
                f.rotation());
    }
}
