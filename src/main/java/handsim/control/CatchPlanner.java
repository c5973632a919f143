package handsim.control;

import handsim.kin.Frame;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.sim.ObjectSpec;
import handsim.sim.RigidState;
import java.util.Optional;

/**
 * Catch planning (sec. 3.6): predict the object's ballistic path, intercept it where its centre
 * crosses the horizontal interception plane while descending, and meet it there with the palm
 * moving at a fraction (70 %) of its velocity. The back of the hand faces along the object's
 * velocity; for a can or club the hand's z axis lies along the object's long axis.
 */
public final class CatchPlanner {

    /**
     * @param duration time from now to the interception (the CATCH state's length), s
     * @param palmTarget palm frame at interception
     * @param palmVelocity palm velocity at interception
     * @param objectPosition, objectVelocity predicted object centre and velocity at interception
     */
    public record Plan(double duration, Frame palmTarget, Vec3 palmVelocity, Vec3 objectPosition, Vec3 objectVelocity) {
    }

    private final Ballistics ballistics;
    private final double planeHeight;
    private final double velocityFraction;
    private final double minDuration;

    public CatchPlanner(Ballistics ballistics, double planeHeight, double velocityFraction, double minDuration) {
        this.ballistics = ballistics;
        this.planeHeight = planeHeight;
        this.velocityFraction = velocityFraction;
        this.minDuration = minDuration;
    }

    /**
     * Plans the interception of {@code object} (shape {@code spec}); {@code readyRotation} is the
     * palm rotation the hand prefers about its dorsal normal (the neutral one).
     */
    public Plan plan(RigidState object, ObjectSpec spec, Quat readyRotation) {
        double t = ballistics.descendingCrossing(object.position(), object.velocity(), planeHeight);
        if (Double.isNaN(t) || t < minDuration) {
            // too soon (or below the plane already): meet it later, lower down
            t = minDuration;
        }
        Vec3 p = ballistics.position(object.position(), object.velocity(), t);
        Vec3 v = ballistics.velocity(object.velocity(), t);
        Vec3 back = v.norm() > 1e-6 ? v.normalized() : Vec3.Y.negate();
        Quat rotation = handRotation(back, longAxisAt(object, spec, t), readyRotation);
        // the object's centre rests one half-thickness off the palm, on the palm side (-y of the hand)
        Vec3 palm = p.plus(back.times(spec.halfThickness()));
        return new Plan(t, new Frame(palm, rotation), v.times(velocityFraction), p, v);
    }

    /** The object's long axis (world) after {@code t} seconds of free rotation at constant angular velocity. */
    static Optional<Vec3> longAxisAt(RigidState object, ObjectSpec spec, double t) {
        return spec.longAxis().map(axis -> {
            Quat spin = Quat.fromRotationVector(object.angularVelocity().times(t));
            return spin.mul(object.orientation()).rotate(axis);
        });
    }

    /**
     * The palm rotation whose y axis (back of the hand) is {@code back} and whose z axis is the
     * long axis projected off {@code back} (either sign, the one nearer the ready pose), or, for
     * round objects, the ready pose's z axis projected likewise.
     */
    static Quat handRotation(Vec3 back, Optional<Vec3> longAxis, Quat readyRotation) {
        Vec3 readyZ = readyRotation.zAxis();
        Vec3 z = longAxis.map(a -> perpendicularPart(a, back)).filter(a -> a.norm() > 0.2).orElse(null);
        if (z == null) {
            z = perpendicularPart(readyZ, back);
            if (z.norm() < 1e-6) {
                z = back.anyPerpendicular();
            }
        } else if (z.dot(readyZ) < 0) {
            z = z.negate();
        }
        z = z.normalized();
        Vec3 x = back.cross(z);
        return Quat.fromFrame(x, back, z);
    }

    private static Vec3 perpendicularPart(Vec3 v, Vec3 n) {
        return v.minus(n.times(v.dot(n)));
    }
}
