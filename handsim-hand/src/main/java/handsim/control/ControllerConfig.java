package handsim.control;

import handsim.config.Json;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Everything tunable of the nominal controller, from {@code configs/controller.json}. The
 * paper's FSM timing figure (Fig. 3) is missing from the sources; the durations here are our
 * choice, documented in the file.
 *
 * @param periodSteps physics steps per controller tick (IK and FSM rate)
 * @param catchMinDuration shortest CATCH state (s): a later interception is planned if the
 *     object would cross the plane sooner
 * @param middleDuration MIDDLE state length (s)
 * @param throwDuration THROW state length (s)
 * @param gobackDuration GOBACK state length (s)
 * @param interceptionHeight height (m) of the horizontal interception plane the object's centre
 *     is caught on
 * @param catchVelocityFraction palm velocity at interception as a fraction of the object's (0.7)
 * @param restPlaneHeight height of the rest plane GOBACK returns to (0.6 m)
 * @param throwEndSpeedFactor palm speed at the end of THROW = factor * |dOffset| / throwDuration
 * @param openTime, closeTime, neutralTime hand pose transition times (s)
 * @param grasps per-object hand poses and catch placement
 * @param headingSearch how the catch planner turns the palm about its normal until the arm can
 *     reach it
 * @param reachIkIterations IK iterations spent judging whether one palm frame is reachable
 * @param replanSpeedChange during CATCH, before any contact, the catch is planned again when the
 *     object's velocity differs from the ballistic prediction by more than this (m/s): it
 *     bounced off something
 * @param fallingTilt how far the palm may tilt from facing a long object that falls straight
 *     down, to lie flat under its axis (rad); more for objects arriving from the side
 * @param release when present, THROW ends when the object would turn far enough in flight
 *     instead of after {@code throwDuration}; a task sets it ({@link #withRelease})
 * @param catchAfterThrow when present, how the catches after the hand's own throws meet the object
 *     (the throw-in is caught with {@code (0, catchVelocityFraction)}); a task sets it ({@link
 *     #withCatchAfterThrow})
 * @param armRest when present, the posture the arm's redundancy is drawn toward in the states
 *     it names; a task sets it ({@link #withArmRest})
 */
public record ControllerConfig(PdGains pd, IkConfig ik, int periodSteps, double catchMinDuration,
        double middleDuration, double throwDuration, double gobackDuration, double interceptionHeight,
        double catchVelocityFraction, double restPlaneHeight, double throwEndSpeedFactor, double openTime,
        double closeTime, double neutralTime, ThrowSpace throwSpace, NominalThrows nominalThrows,
        Grasp.Table grasps, CatchPlanner.HeadingSearch headingSearch, int reachIkIterations,
        double replanSpeedChange, double fallingTilt, Optional<ClosedLoopRelease> release,
        Optional<CatchStyle> catchAfterThrow, Optional<ArmRest> armRest) {

    public static ControllerConfig load(Path file) {
        return parse(Json.load(file));
    }

    public static ControllerConfig parse(Json j) {
        j.allow("comment");
        Json fsm = j.get("fsm");
        fsm.allow("comment");
        Json catching = j.get("catch");
        catching.allow("comment", "headingComment", "replanComment", "fallingTiltComment");
        Json poses = j.get("handPoses");
        poses.allow("comment");
        Json throwing = j.get("throw");
        throwing.allow("comment", "nominalComment");
        ControllerConfig c = new ControllerConfig(
                PdGains.parse(j.get("pd")),
                IkConfig.parse(j.get("ik")),
                j.integer("periodSteps", 1, 1000),
                fsm.positive("catchMinDuration"),
                fsm.positive("middleDuration"),
                fsm.positive("throwDuration"),
                fsm.positive("gobackDuration"),
                catching.number("interceptionHeight"),
                catching.number("velocityFraction", 0, 1),
                catching.number("restPlaneHeight"),
                throwing.number("endSpeedFactor", 0, 3),
                poses.positive("openTime"),
                poses.positive("closeTime"),
                poses.positive("neutralTime"),
                ThrowSpace.parse(throwing.get("space")),
                NominalThrows.parse(throwing.get("nominal")),
                Grasp.Table.parse(j.get("grasps")),
                new CatchPlanner.HeadingSearch(Math.toRadians(catching.number("headingStepDeg", 1, 90)),
                        Math.toRadians(catching.number("headingMaxDeg", 0, 180)),
                        catching.positive("reachPositionTolerance"),
                        Math.toRadians(catching.positive("reachRotationToleranceDeg"))),
                catching.integer("reachIkIterations", 1, 10000),
                catching.positive("replanSpeedChange"),
                Math.toRadians(catching.number("fallingTiltDeg", 0, 90)),
                Optional.empty(), Optional.empty(), Optional.empty());
        for (Json node : new Json[] {fsm, catching, poses, throwing, j}) {
            node.requireNoUnknownFields();
        }
        if (c.nominalThrows.entries().stream().anyMatch(e -> !c.throwSpace.contains(e.params()))) {
            throw throwing.fieldError("nominal", "every nominal throw must lie inside throw.space");
        }
        return c;
    }

    /** This config with THROW ending by {@code r} (checked against the THROW duration). */
    public ControllerConfig withRelease(ClosedLoopRelease r) {
        if (r.earliest() > throwDuration) {
            throw new IllegalArgumentException("a closed-loop release's earliest end (" + r.earliest()
                    + " s) must lie within THROW (" + throwDuration + " s)");
        }
        return with(Optional.of(r), catchAfterThrow, armRest);
    }

    /** This config with the catches after the hand's throws meeting the object as {@code style} says. */
    public ControllerConfig withCatchAfterThrow(CatchStyle style) {
        return with(release, Optional.of(style), armRest);
    }

    /** This config with the arm's redundancy drawn toward {@code rest} in the states it names ({@link ArmRest}). */
    public ControllerConfig withArmRest(ArmRest rest) {
        return with(release, catchAfterThrow, Optional.of(rest));
    }

    /** The controller's own way of meeting an object: on the interception plane at catchVelocityFraction. */
    public CatchStyle catchStyle() {
        return new CatchStyle(0, catchVelocityFraction);
    }

    private ControllerConfig with(Optional<ClosedLoopRelease> r, Optional<CatchStyle> c, Optional<ArmRest> a) {
        return new ControllerConfig(pd, ik, periodSteps, catchMinDuration, middleDuration, throwDuration, gobackDuration,
                interceptionHeight, catchVelocityFraction, restPlaneHeight, throwEndSpeedFactor, openTime, closeTime,
                neutralTime, throwSpace, nominalThrows, grasps, headingSearch, reachIkIterations, replanSpeedChange, fallingTilt,
                r, c, a);
    }
}
