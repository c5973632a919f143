package handsim.task;

import handsim.config.Json;
import handsim.control.ArmRest;
import handsim.control.CatchStyle;
import handsim.control.ClosedLoopRelease;
import handsim.control.ControllerConfig;
import handsim.control.ThrowParameters;
import handsim.control.ThrowSpace;
import handsim.math.Vec3;
import handsim.sim.Simulator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;

/**
 * Flip the object and catch it, over and over (paper sec. 4.4). A flip is counted from the net
 * end-over-end turn of the object's long axis in flight ({@link LoopRecord#flightRotation}, from
 * the release, the last hand contact on the way up, to the catch, the first contact on the way
 * down, by {@link FlightTracker}; turning about the vertical, a flat spin, and a wobble do not
 * count): {@code flips = floor((rotation + tolerance) / flipAngle)}, with flipAngle half a turn for a can (end for end is the same can) and a whole
 * turn for a club (the handle comes back to the hand). A flip must be caught properly: held in
 * the hand when MIDDLE ends and lying in it, its long axis at most {@code maxCatchTilt} out of
 * the palm's plane ({@link LoopRecord#catchTilt}; a can standing on end in the palm is no catch
 * to flip from). Reward eq. (7) as read in SPEC.md: a properly caught throw that flipped
 * scores {@code exp(-sharpness |p_p - p_d|) + flipBonus}, anything else {@code -missWeight
 * |p_p - p_d|}; p_p is where the object was caught (or came down, when dropped) and p_d a spot
 * above the hand where a good flip comes down.
 */
public final class FlipTask implements ThrowTask {

    /**
     * One object's flip.
     *
     * @param flipAngle turning of the long axis that makes one flip (rad)
     * @param nominal the hand-tuned flip throw
     * @param release how THROW lets go of this object, when not after its fixed duration
     * @param catchAfterThrow how the catch after each flip meets this object, when not as the controller's
     * @param armRest the arm posture the arm's redundancy is drawn toward, and in which states, when any
     */
    public record ObjectFlip(double flipAngle, ThrowParameters nominal, Optional<ClosedLoopRelease> release,
            Optional<CatchStyle> catchAfterThrow, Optional<ArmRest> armRest) {

        ObjectFlip with(Optional<CatchStyle> catching, Optional<ArmRest> rest) {
            return new ObjectFlip(flipAngle, nominal, release, catching, rest);
        }
    }

    /**
     * {@code configs/tasks/flip.json}.
     *
     * @param tolerance a flip is counted this much short of its angle (rad)
     * @param maxCatchTilt a catch counts when the long axis stands at most this far out of the palm's plane (rad)
     * @param endFirstTilt a failed throw whose object came back to the hand with its long axis at least this far out
     *     of the horizontal failed by arriving end-first (rad; {@link Failure#ARRIVED_END_FIRST})
     * @param sharpness the 10 of eq. (7) (1/m)
     * @param missWeight the 0.1 of eq. (7)'s miss term (1/m)
     * @param flipBonus r_flip of eq. (7)
     * @param targetOffset p_d relative to the neutral palm centre (m, world)
     * @param space the box of throw parameters: flips need far more palm rotation than the other tasks
     * @param objects the objects that can be flipped, by name
     * @param evaluationLoops the most flip-and-catch loops an evaluation episode runs to by default
     */
    public record Config(double tolerance, double maxCatchTilt, double endFirstTilt, double sharpness, double missWeight, double flipBonus,
            Vec3 targetOffset, ThrowSpace space, Map<String, ObjectFlip> objects, int evaluationLoops) {

        public Config {
            objects = Map.copyOf(objects);
        }

        public static Config parse(Json j) {
            j.allow("comment", "maxCatchTiltComment", "endFirstTiltComment", "evaluationLoopsComment");
            Json objs = j.get("objects");
            objs.allow("comment");
            Map<String, ObjectFlip> flips = new LinkedHashMap<>();
            ThrowSpace space = ThrowSpace.parse(j.get("throwSpace"));
            for (String name : objs.fieldNames()) {
                if (name.equals("comment")) {
                    continue;
                }
                Json o = objs.get(name);
                o.allow("comment");
                Json n = o.get("nominal");
                n.allow("comment");
                ThrowParameters nominal = new ThrowParameters(n.vec3("dOffset"), n.vec3("rTargetDeg").times(Math.PI / 180),
                        n.number("tOpen", 0, 10));
                n.requireNoUnknownFields();
                if (!space.contains(nominal)) {
                    throw o.fieldError("nominal", "must lie inside throwSpace, got " + nominal);
                }
                Optional<ClosedLoopRelease> release = o.has("release") ? Optional.of(ClosedLoopRelease.parse(o.get("release")))
                        : Optional.empty();
                Optional<CatchStyle> catching = o.has("catch") ? Optional.of(CatchStyle.parse(o.get("catch"))) : Optional.empty();
                Optional<ArmRest> rest = o.has("armRest") ? Optional.of(ArmRest.parse(o.get("armRest"))) : Optional.empty();
                flips.put(name, new ObjectFlip(Math.toRadians(o.number("flipAngleDeg", 1, 3600)), nominal, release, catching, rest));
                o.requireNoUnknownFields();
            }
            Config c = new Config(Math.toRadians(j.number("toleranceDeg", 0, 180)),
                    Math.toRadians(j.number("maxCatchTiltDeg", 0, 90)), Math.toRadians(j.number("endFirstTiltDeg", 0, 90)),
                    j.positive("sharpness"), j.number("missWeight", 0, 100), j.number("flipBonus", 0, 100), j.vec3("targetOffset"),
                    space, flips, j.integer("evaluationLoops", 0, 100000));
            j.requireNoUnknownFields();
            return c;
        }
    }

    private final Config config;
    private final String object;
    private final ObjectFlip flip;
    private final Vec3 target;

    /** The flip task for {@code object}, which the config must list. */
    public FlipTask(Config config, String object, Vec3 neutralPalm) {
        this(config, object, settingsFor(config, object), neutralPalm.plus(config.targetOffset()));
    }

    private static ObjectFlip settingsFor(Config config, String object) {
        ObjectFlip flip = config.objects().get(object);
        if (flip == null) {
            throw new IllegalArgumentException("the flip task has no settings for a " + object + " (configs/tasks/flip.json lists "
                    + String.join(", ", config.objects().keySet()) + ")");
        }
        return flip;
    }

    private FlipTask(Config config, String object, ObjectFlip flip, Vec3 target) {
        this.config = config;
        this.object = object;
        this.flip = flip;
        this.target = target;
    }

    /** This task with the catches after the hand's throws meeting the object as {@code style} says, not as its config says. */
    public FlipTask catchingAs(CatchStyle style) {
        return new FlipTask(config, object, flip.with(Optional.of(style), flip.armRest()), target);
    }

    /** This task with the arm's redundancy left to the IK, not drawn toward the object's {@link ArmRest}. */
    public FlipTask withoutArmRest() {
        return new FlipTask(config, object, flip.with(flip.catchAfterThrow(), Optional.empty()), target);
    }

    /** The turning of the long axis that makes one flip (rad). */
    public double flipAngle() {
        return flip.flipAngle();
    }

    /** Whole flips made by a loop's throw (0 for loop 0). */
    public int flips(LoopRecord loop) {
        double rotation = loop.flightRotation();
        return Double.isNaN(rotation) ? 0 : (int) Math.floor((rotation + config.tolerance()) / flip.flipAngle());
    }

    public String object() {
        return object;
    }

    @Override
    public String name() {
        return "flip";
    }

    @Override
    public int goalSize() {
        return 0;
    }

    @Override
    public void start(Simulator sim, long seed) {
        // nothing to set up: every throw aims at a flip
    }

    @Override
    public double[] goal() {
        return new double[0];
    }

    @Override
    public void advance() {
        // the goal does not change
    }

    @Override
    public ThrowParameters nominalThrow() {
        return flip.nominal();
    }

    @Override
    public ThrowSpace throwSpace(ThrowSpace fallback) {
        return config.space();
    }

    @Override
    public ControllerConfig controller(ControllerConfig base) {
        ControllerConfig released = flip.release().map(base::withRelease).orElse(base);
        ControllerConfig caught = flip.catchAfterThrow().map(released::withCatchAfterThrow).orElse(released);
        return flip.armRest().map(caught::withArmRest).orElse(caught);
    }

    /** eq. (7). */
    @Override
    public double reward(LoopRecord loop) {
        Vec3 where = loop.caught() ? loop.catchPoint() : loop.landing();
        double d = where == null ? 0 : where.distance(target);
        return success(loop) ? Math.exp(-config.sharpness() * d) + config.flipBonus() : -config.missWeight() * d;
    }

    @Override
    public boolean success(LoopRecord loop) {
        return properCatch(loop) && flips(loop) >= 1;
    }

    /**
     * Only a throw that turned the object far enough before the hand touched it: another catch
     * meets it a few hundredths of a second earlier or later, a few degrees of turn apart.
     */
    @Override
    public boolean catchMayMatter(LoopRecord loop) {
        return flips(loop) >= 1;
    }


    /**
     * Why a throw failed the task, one reason per throw, the first that applies: it came back
     * end-first (its turn in flight was wrong, and the catch could only drop it or hold it
     * standing), it was dropped, it was caught standing, or it was caught lying but turned too
     * little to flip.
     */
    public enum Failure {
        ARRIVED_END_FIRST, DROPPED, CAUGHT_STANDING, NO_FLIP;

        /** The name in the JSON and CSV: {@code arrived_end_first}, {@code dropped}, ... */
        public String label() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    /** Why the throw of {@code loop} (index >= 1) failed, or empty when it succeeded. */
    public Optional<Failure> failure(LoopRecord loop) {
        if (success(loop)) {
            return Optional.empty();
        }
        if (loop.arrivalTilt() >= config.endFirstTilt()) {
            return Optional.of(Failure.ARRIVED_END_FIRST);
        }
        return Optional.of(!loop.caught() ? Failure.DROPPED : !properCatch(loop) ? Failure.CAUGHT_STANDING : Failure.NO_FLIP);
    }


    /** Held in the hand and lying in it: the long axis at most maxCatchTilt out of the palm's plane. */
    public boolean properCatch(LoopRecord loop) {
        return loop.caught() && !(loop.catchTilt() > config.maxCatchTilt());
    }
}
