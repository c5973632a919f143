package handsim.task;


import handsim.config.Json;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.sim.ObjectSpec;
import handsim.sim.RigidState;
import java.nio.file.Path;
import java.util.SplittableRandom;

/**
 * The seeded distribution of throws toward the hand used to start episodes
 * ({@code configs/launch.json}): a start point offset from the neutral palm centre, an arrival
 * point on the interception plane near it, a flight time, and for long objects a tilt and spin.
 */
public record LaunchDistribution(double[] startX, double[] startY, double[] startZ, double[] arrivalX,
        double[] arrivalZ, double[] flightTime, double tiltDeg, double spin) {

    public static LaunchDistribution load(Path file) {
        return parse(Json.load(file));
    }

    public static LaunchDistribution parse(Json j) {
        j.allow("comment");
        Json start = j.get("startOffset");
        Json arrival = j.get("arrivalOffset");
        LaunchDistribution d = new LaunchDistribution(start.range("x"), start.range("y"), start.range("z"),
                arrival.range("x"), arrival.range("z"), j.range("flightTime"), j.number("tiltDeg", 0, 90),
                j.number("spin", 0, 100));
        if (!(d.flightTime[0] > 0)) {
            throw j.fieldError("flightTime", "must be > 0 s, got " + d.flightTime[0]);
        }
        for (Json node : new Json[] {start, arrival, j}) {
            node.requireNoUnknownFields();
        }
        return d;
    }

    /**
     * Draws a launch that crosses height {@code planeHeight} near {@code palm} (the neutral palm
     * centre) after the drawn flight time, descending.
     */
    public RigidState sample(SplittableRandom rng, Vec3 palm, double planeHeight, ObjectSpec spec, Vec3 gravity) {
        Vec3 start = palm.plus(new Vec3(draw(rng, startX), draw(rng, startY), draw(rng, startZ)));
        Vec3 arrival = new Vec3(palm.x() + draw(rng, arrivalX), planeHeight, palm.z() + draw(rng, arrivalZ));
        double t = draw(rng, flightTime);
        RigidState flight = ballisticLaunch(start, arrival, t, gravity);
        Quat orientation = Quat.IDENTITY;
        Vec3 spinVector = Vec3.ZERO;
        if (spec.longAxis().isPresent()) {
            double heading = 2 * Math.PI * rng.nextDouble();
            double tilt = Math.toRadians(tiltDeg) * (2 * rng.nextDouble() - 1);
            Vec3 dir = new Vec3(Math.cos(heading) * Math.cos(tilt), Math.sin(tilt), Math.sin(heading) * Math.cos(tilt));
            orientation = Quat.between(spec.longAxis().get(), dir);
            double spinAxisHeading = 2 * Math.PI * rng.nextDouble();
            spinVector = new Vec3(Math.cos(spinAxisHeading), 0, Math.sin(spinAxisHeading)).times(spin * rng.nextDouble());
        }
        return new RigidState(flight.position(), orientation, flight.velocity(), spinVector);
    }

    private static double draw(SplittableRandom rng, double[] range) {
        return range[0] + rng.nextDouble() * (range[1] - range[0]);
    }

    /** The launch state that carries a point mass from {@code from} to {@code to} in {@code time} under gravity. */
    public static RigidState ballisticLaunch(Vec3 from, Vec3 to, double time, Vec3 gravity) {
        // to = from + v t + g t^2 / 2
        Vec3 v = to.minus(from).minus(gravity.times(0.5 * time * time)).times(1.0 / time);
        return RigidState.at(from, v);
    }
}
