package handsim.control;

import handsim.kin.Frame;
import handsim.math.EndOverEnd;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.sim.ObjectSpec;
import handsim.sim.RigidState;
import java.util.Optional;

/**
 * Catch planning (sec. 3.6): predict the object's ballistic path, intercept it where its centre
 * crosses the horizontal interception plane while descending, and meet it there with the palm
 * moving at a fraction (70 %) of its velocity. The back of the hand faces along the object's
 * velocity; for a can or club the hand's z axis lies along the object's long axis. The paper
 * asks for both; where they conflict the palm tilts toward lying flat under the axis, fully for
 * an object arriving level, not at all for one falling straight down ({@link #tiltLimit}).
 *
 * <p>The arm cannot turn the palm to every heading about its normal (wrist and shoulder limits),
 * so the planner asks a {@link Reach} whether the arm can place the palm there and, if not,
 * turns the hand about the palm normal in steps, nearest headings first, until it can: the
 * object then lies across the palm at a slant, as a can does in a power grasp.
 */
public final class CatchPlanner {

    /** How closely the arm can place the palm at a frame: the inverse kinematics residual. */
    @FunctionalInterface
    public interface Reach {
        DlsIk.Residual residual(Frame palm);
    }

    /**
     * The search over headings about the palm normal.
     *
     * @param angleStep step between tried headings (rad)
     * @param maxAngle largest turn away from the preferred heading (rad)
     * @param positionTolerance a palm frame counts as reachable within this IK position residual (m)
     * @param rotationTolerance ... and this rotation residual (rad)
     */
    public record HeadingSearch(double angleStep, double maxAngle, double positionTolerance, double rotationTolerance) {
    }

    /**
     * @param duration time from now to the interception (the CATCH state's length), s
     * @param palmTarget palm frame at interception
     * @param palmVelocity palm velocity at interception
     * @param objectPosition, objectVelocity predicted object centre and velocity at interception
     */
    public record Plan(double duration, Frame palmTarget, Vec3 palmVelocity, Vec3 objectPosition, Vec3 objectVelocity) {
    }

    /** Below this sine of the angle between velocity and long axis the object flies end-first. */
    private static final double MIN_ACROSS = 0.3;

    private final Ballistics ballistics;
    private final double planeHeight;
    private final double velocityFraction;
    private final double minDuration;
    private final HeadingSearch search;
    private final double fallingTilt;

    /**
     * @param fallingTilt how far the palm may tilt from facing a vertically falling long object
     *     to lie flat under its axis (rad; see {@link #tiltLimit})
     */
    public CatchPlanner(Ballistics ballistics, double planeHeight, double velocityFraction, double minDuration,
            HeadingSearch search, double fallingTilt) {
        this.ballistics = ballistics;
        this.planeHeight = planeHeight;
        this.velocityFraction = velocityFraction;
        this.minDuration = minDuration;
        this.search = search;
        this.fallingTilt = fallingTilt;
    }

    /**
     * Plans the interception of {@code object} (shape {@code spec}), met where {@code grasp}
     * places it on the hand; {@code readyRotation} is the palm rotation the hand prefers about
     * its dorsal normal (the neutral one); {@code reach} says where the arm can put the palm.
     */
    public Plan plan(RigidState object, ObjectSpec spec, Grasp grasp, Quat readyRotation, Reach reach) {
        return plan(object, spec, grasp, readyRotation, reach, new CatchStyle(0, velocityFraction));
    }

    /** {@link #plan} meeting the object as {@code style} says instead of this planner's own way. */
    public Plan plan(RigidState object, ObjectSpec spec, Grasp grasp, Quat readyRotation, Reach reach, CatchStyle style) {
        return plan(object, spec, grasp, readyRotation, reach, style, null);
    }

    /**
     * {@link #plan} of an object in flight that has turned {@code turnSoFar} since it left the
     * hand (the summed rotation vector of its long axis's turns, {@link EndOverEnd#step}; null
     * when not known), for a level search that asks for a turn ({@link CatchStyle.Level#minTurn}).
     */
    public Plan plan(RigidState object, ObjectSpec spec, Grasp grasp, Quat readyRotation, Reach reach, CatchStyle style,
            Vec3 turnSoFar) {
        double t = style.level() == null || spec.longAxis().isEmpty() ? interceptionTime(object, style.planeShift())
                : levelInterceptionTime(object, spec, style.planeShift(), style.level(), turnSoFar);
        Vec3 p = ballistics.position(object.position(), object.velocity(), t);
        Vec3 v = ballistics.velocity(object.velocity(), t);
        Optional<Vec3> axis = longAxisAt(object, spec, t);
        Vec3 back = backOfHand(v, axis, fallingTilt);
        Quat preferred = handRotation(back, axis, readyRotation);
        Frame palm = reachableHeading(preferred, p, grasp.objectInPalm(spec.halfThickness()).plus(style.offset()),
                axis.isPresent(), reach);
        return new Plan(t, palm, v.times(style.velocityFraction()), p, v);
    }

    /** When the object's centre crosses the plane raised by {@code shift} going down; not sooner than the shortest CATCH. */
    private double interceptionTime(RigidState object, double shift) {
        double t = ballistics.descendingCrossing(object.position(), object.velocity(), planeHeight + shift);
        // too soon (or below the plane already): meet it later, lower down
        return Double.isNaN(t) || t < minDuration ? minDuration : t;
    }

    /**
     * The interception time on the plane nearest {@code shift}, within the search's reach below
     * and above, where the long axis is predicted ({@link #longAxisAt}) to lie level within its
     * tilt and, when the search asks for a turn and {@code turnSoFar} is known, the object to
     * have turned that far ({@link #predictedTurn}). When it is level on some plane but turned on
     * none of those, on the nearest turned plane within the search's turn tilt, or else on the
     * most turned plane within it (when it is more turned than the nearest level one), or else on
     * the nearest level one; when it is level on none, on the plane where it is nearest to level.
     */
    private double levelInterceptionTime(RigidState object, ObjectSpec spec, double shift, CatchStyle.Level level,
            Vec3 turnSoFar) {
        int below = (int) Math.floor(level.below() / level.step() + 1e-9);
        int above = (int) Math.floor(level.above() / level.step() + 1e-9);
        boolean askTurn = level.minTurn() > 0 && turnSoFar != null;
        double nearestLevel = Double.NaN;
        double levelTurn = Double.NaN;
        double nearestTurned = Double.NaN;
        double mostTurned = Double.NaN;
        double mostTurn = Double.NEGATIVE_INFINITY;
        double bestTime = interceptionTime(object, shift);
        double bestTilt = Double.POSITIVE_INFINITY;
        for (int k = 0; k <= 2 * Math.max(below, above); k++) {
            int n = nearestFirst(k);
            if (n > above || -n > below) {
                continue;
            }
            double t = interceptionTime(object, shift + n * level.step());
            double tilt = Math.asin(Math.min(1, Math.abs(longAxisAt(object, spec, t).orElseThrow().y())));
            double turn = askTurn ? predictedTurn(object, spec, turnSoFar, t) : Double.POSITIVE_INFINITY;
            boolean turned = turn >= level.minTurn();
            if (tilt <= level.tilt() && turned) {
                return t;
            }
            if (tilt <= level.tilt() && Double.isNaN(nearestLevel)) {
                nearestLevel = t;
                levelTurn = turn;
            }
            if (tilt <= level.turnTilt() && turned && Double.isNaN(nearestTurned)) {
                nearestTurned = t;
            }
            if (tilt <= level.turnTilt() && turn > mostTurn) {
                mostTurn = turn;
                mostTurned = t;
            }
            if (tilt < bestTilt) {
                bestTilt = tilt;
                bestTime = t;
            }
        }
        if (Double.isNaN(nearestLevel)) {
            return bestTime;
        }
        return !Double.isNaN(nearestTurned) ? nearestTurned : mostTurn > levelTurn ? mostTurned : nearestLevel;
    }

    /** Step (s) of the predicted flight along which {@link #predictedTurn} sums the axis's turns. */
    private static final double TURN_STEP = 0.005;

    /**
     * The net end-over-end turn (rad, {@link EndOverEnd#net}) the object will have made {@code t}
     * seconds from now, having turned {@code turnSoFar} already: its torque-free long axis
     * ({@link FreeRotation}) followed in {@link #TURN_STEP} ticks, their turns summed as the
     * flip criterion sums them.
     */
    double predictedTurn(RigidState object, ObjectSpec spec, Vec3 turnSoFar, double t) {
        Vec3 axis0 = spec.longAxis().orElseThrow();
        FreeRotation free = new FreeRotation(spec.mass().inertia());
        FreeRotation.Spin spin = new FreeRotation.Spin(object.orientation(), object.angularVelocity());
        Vec3 axis = spin.orientation().rotate(axis0);
        Vec3 turn = turnSoFar;
        int steps = (int) Math.ceil(Math.max(0, t) / TURN_STEP);
        for (int i = 0; i < steps; i++) {
            spin = free.after(spin.orientation(), spin.angularVelocity(), t / steps);
            Vec3 next = spin.orientation().rotate(axis0);
            turn = turn.plus(EndOverEnd.step(axis, next));
            axis = next;
        }
        return EndOverEnd.net(turn, ballistics.gravity().normalized().negate());
    }

    /** The k-th step of a search outward from where it starts, nearest first: 0, +1, -1, +2, -2, ... */
    private static int nearestFirst(int k) {
        return (k % 2 == 1 ? 1 : -1) * ((k + 1) / 2);
    }

    /**
     * The palm frame that puts the object's centre {@code p} at {@code objectInPalm}, turned
     * about the palm normal as little as possible from {@code preferred} while reachable; the
     * best-reached one if none is. A long object lies along the hand either way round, so for
     * it a half turn counts as no turn.
     */
    private Frame reachableHeading(Quat preferred, Vec3 p, Vec3 objectInPalm, boolean symmetric, Reach reach) {
        Frame best = null;
        double bestMiss = Double.POSITIVE_INFINITY;
        int steps = (int) Math.floor(search.maxAngle() / search.angleStep() + 1e-9);
        for (int k = 0; k <= 2 * steps; k++) {
            // each heading also tried half a turn round for long objects
            double turn = nearestFirst(k) * search.angleStep();
            for (double flip : symmetric ? new double[] {0, Math.PI} : new double[] {0}) {
                Quat r = preferred.mul(Quat.fromAxisAngle(Vec3.Y, turn + flip));
                Frame palm = new Frame(p.minus(r.rotate(objectInPalm)), r);
                DlsIk.Residual res = reach.residual(palm);
                if (res.position() <= search.positionTolerance() && res.rotation() <= search.rotationTolerance()) {
                    return palm;
                }
                // unreachable everywhere: keep the frame the arm gets closest to (1 rad weighs as 0.1 m)
                double miss = res.position() + 0.1 * res.rotation();
                if (miss < bestMiss) {
                    bestMiss = miss;
                    best = palm;
                }
            }
        }
        return best;
    }

    /**
     * The direction the back of the hand faces: along the incoming velocity, or, for an object
     * with a long axis, turned from it toward the velocity's part across that axis (so the
     * object lands flat on the palm instead of on one end) by at most {@link #tiltLimit}
     * (unless the object flies nearly end-first, where the velocity itself is kept).
     */
    static Vec3 backOfHand(Vec3 velocity, Optional<Vec3> longAxis, double fallingTilt) {
        Vec3 back = velocity.norm() > 1e-6 ? velocity.normalized() : Vec3.Y.negate();
        if (longAxis.isPresent()) {
            Vec3 across = perpendicularPart(back, longAxis.get());
            if (across.norm() > MIN_ACROSS) {
                Vec3 flat = across.normalized();
                double tilt = Math.acos(Math.max(-1, Math.min(1, back.dot(flat))));
                double limit = tiltLimit(back, fallingTilt);
                return tilt <= limit ? flat : Quat.fromAxisAngle(back.cross(flat).normalized(), limit).rotate(back);
            }
        }
        return back;
    }

    /**
     * How far the back of the hand may turn away from the arrival direction {@code back} (unit;
     * y is up, as in {@link Ballistics}) to lie flat under the long axis: {@code fallingTilt}
     * for an object falling straight down, growing linearly with the arrival's horizontal part
     * to a quarter turn for one arriving level. A tumbling object coming down onto a level palm
     * settles on it, a tilted palm lets it slide off (docs/experiments.md, "Catch"); an object arriving from
     * the side is met flat.
     */
    static double tiltLimit(Vec3 back, double fallingTilt) {
        double horizontal = Math.sqrt(back.x() * back.x() + back.z() * back.z());
        return fallingTilt + (Math.PI / 2 - fallingTilt) * Math.min(1, horizontal);
    }

    /**
     * The object's long axis (world) after {@code t} seconds of torque-free rotation ({@link
     * FreeRotation}: a roll about the axis itself does not tip it).
     */
    static Optional<Vec3> longAxisAt(RigidState object, ObjectSpec spec, double t) {
        return spec.longAxis().map(axis -> new FreeRotation(spec.mass().inertia())
                .after(object.orientation(), object.angularVelocity(), t).orientation().rotate(axis));
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
