package handsim.control;

import handsim.config.Json;
import handsim.math.EndOverEnd;
import handsim.math.Vec3;
import handsim.sim.RigidState;

/**
 * A THROW that lets go when the object would turn far enough in flight, instead of after its
 * fixed duration (handsim's extension of sec. 3.6 for flips; off unless a task asks for it).
 * A can gains most of its end-over-end spin in the last few tens of milliseconds of the paper's
 * THROW, as the fingers open and the palm stops, and by how much varies from throw to throw
 * (docs/experiments.md, "Throw"). So the controller watches the object: THROW ends, and GOBACK's palm
 * falls away and lets go, once the predicted turn reaches {@code turn}; a throw still short of it
 * at the end of THROW goes on (the palm at its end velocity, turning on at its rate) for at most
 * {@code extension}.
 *
 * @param turn predicted end-over-end turn in flight at which THROW ends (rad)
 * @param earliest THROW does not end sooner than this (s; at most the THROW duration)
 * @param extension how long THROW may run past its duration while the predicted turn is short (s)
 */
public record ClosedLoopRelease(double turn, double earliest, double extension) {

    public static ClosedLoopRelease parse(Json j) {
        j.allow("comment");
        ClosedLoopRelease r = new ClosedLoopRelease(Math.toRadians(j.number("predictedTurnDeg", 1, 3600)),
                j.number("earliest", 0, 1), j.number("extension", 0, 1));
        j.requireNoUnknownFields();
        return r;
    }

    /**
     * The end-over-end turn (rad) of an object let go now: its end-over-end rate times the time
     * until its centre comes down through {@code planeHeight}, where it is caught; 0 when it
     * would not come down there.
     *
     * @param axis the object's long axis (world, unit)
     */
    static double predictedTurn(RigidState object, Vec3 axis, Ballistics ballistics, double planeHeight) {
        double flight = ballistics.descendingCrossing(object.position(), object.velocity(), planeHeight);
        Vec3 up = ballistics.gravity().normalized().negate();
        return Double.isNaN(flight) ? 0 : EndOverEnd.rate(object.angularVelocity(), axis, up) * flight;
    }

    /** Whether THROW is over {@code t} seconds in, of its {@code duration}, with the predicted turn {@code predicted}. */
    boolean throwOver(double t, double duration, double predicted) {
        return t >= earliest && predicted >= turn || t >= duration + extension;
    }
}
