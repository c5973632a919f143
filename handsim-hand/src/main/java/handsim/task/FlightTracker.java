package handsim.task;

import handsim.math.EndOverEnd;
import handsim.math.Vec3;

/**
 * One throw's flight, followed tick by tick: from the release (the last tick with a hand
 * contact while the object still rises) to the catch (the first contact once it comes down),
 * the net end-over-end turn of the object's long axis in between (the tick-by-tick turns summed
 * as rotation vectors, {@link EndOverEnd#step}, of which the horizontal part counts,
 * {@link EndOverEnd#net}), and how fast it was turning so as it left the hand
 * ({@link EndOverEnd#rate}).
 * A touch on the way up, when the still-rising hand meets the object again, is part of the
 * throw: the flight begins after it. Engine-free, so the flip criterion is tested on scripted
 * flights.
 */
final class FlightTracker {

    private enum Stage { BEFORE_RELEASE, FLYING, LANDED }

    /** The world's up, against gravity: end-over-end turns are about axes square to it. */
    private final Vec3 up;
    private Stage stage = Stage.BEFORE_RELEASE;
    private Vec3 lastAxis;
    /** The summed rotation vector of the long axis's turns in flight (rad). */
    private Vec3 turn = Vec3.ZERO;
    private double releaseSpin = Double.NaN;
    private Vec3 catchPoint;
    private double arrivalTilt = Double.NaN;

    FlightTracker(Vec3 up) {
        this.up = up.normalized();
    }

    /** An independent tracker at the same point of the same flight. */
    FlightTracker copy() {
        return new FlightTracker(this);
    }

    private FlightTracker(FlightTracker o) {
        up = o.up;
        stage = o.stage;
        lastAxis = o.lastAxis;
        turn = o.turn;
        releaseSpin = o.releaseSpin;
        catchPoint = o.catchPoint;
        arrivalTilt = o.arrivalTilt;
    }

    /** Starts following a new throw, not yet released. */
    void reset() {
        stage = Stage.BEFORE_RELEASE;
        lastAxis = null;
        turn = Vec3.ZERO;
        releaseSpin = Double.NaN;
        catchPoint = null;
        arrivalTilt = Double.NaN;
    }

    /**
     * One tick of the throw.
     *
     * @param touching the hand touched the object since the previous tick
     * @param throwBegun the controller has begun the throw (a loss of contact before it is no release)
     * @param axis the object's long axis (world), or null for an object without one
     * @param angularVelocity the object's angular velocity (world, rad/s)
     */
    void observe(boolean touching, boolean throwBegun, Vec3 position, Vec3 velocity, Vec3 axis, Vec3 angularVelocity) {
        switch (stage) {
            case BEFORE_RELEASE -> {
                if (!touching && throwBegun) {
                    stage = Stage.FLYING;
                    turn = Vec3.ZERO;
                    lastAxis = axis;
                    releaseSpin = axis == null ? Double.NaN : EndOverEnd.rate(angularVelocity, axis, up);
                }
            }
            case FLYING -> {
                if (touching) {
                    if (velocity.dot(up) > 0) {
                        stage = Stage.BEFORE_RELEASE; // touched on the way up: still the throw
                    } else {
                        stage = Stage.LANDED;
                        catchPoint = position;
                        arrivalTilt = axis == null ? Double.NaN : Math.asin(Math.min(1, Math.abs(axis.dot(up))));
                    }
                } else if (axis != null) {
                    turn = turn.plus(EndOverEnd.step(lastAxis, axis));
                    lastAxis = axis;
                }
            }
            case LANDED -> {
                // the catch is recorded; nothing more to follow
            }
        }
    }

    /** The net end-over-end turn of the long axis in flight so far (rad; 0 before the release). */
    double rotation() {
        return EndOverEnd.net(turn, up);
    }

    /**
     * How fast the long axis turned end over end in the first tick of the flight (rad/s; NaN
     * before the release and for objects without a long axis). Free flight keeps it nearly
     * constant, so the turn in flight is about this rate times the flight's duration.
     */
    double releaseSpin() {
        return releaseSpin;
    }

    /**
     * How far the long axis stood out of the horizontal at the catch (rad: 0 arriving lying,
     * pi/2 end-first; NaN before the catch and for objects without a long axis).
     */
    double arrivalTilt() {
        return arrivalTilt;
    }

    /** Where the object's centre was at the catch (null before it). */
    Vec3 catchPoint() {
        return catchPoint;
    }
}
