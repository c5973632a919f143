package handsim.task;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.TestSupport;
import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.ArmRest;
import handsim.control.CatchStyle;
import handsim.control.ClosedLoopRelease;
import handsim.control.ControllerConfig;
import handsim.control.Phase;
import handsim.math.EndOverEnd;
import handsim.math.Vec3;
import java.nio.file.Files;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Flip detection and eq. (7) on scripted flights: the count comes from the long axis's net
 * end-over-end turn in flight (half turns for a can, whole turns for a club, 45 deg of tolerance
 * in the shipped configs/tasks/flip.json).
 */
@Tag("fast")
class FlipTaskTest {

    private final FlipTask can = TestSupport.configs().flip().newTask("can");
    private final FlipTask club = TestSupport.configs().flip().newTask("club");
    private final Vec3 target = TestSupport.neutralPalm().plus(new Vec3(0, 0.12, 0));

    @Test
    void flipsAreCountedInWholeFlipAnglesWithTheTolerance() {
        // can: 180 deg a flip, counted from 135 deg on
        assertEquals(0, can.flips(ScriptedLoops.flight(0, true, target)));
        assertEquals(0, can.flips(ScriptedLoops.flight(130, true, target)), "a near miss: 5 deg short of the tolerance");
        assertEquals(1, can.flips(ScriptedLoops.flight(140, true, target)));
        assertEquals(1, can.flips(ScriptedLoops.flight(180, true, target)));
        assertEquals(2, can.flips(ScriptedLoops.flight(360, true, target)), "two half turns");
        // club: a whole turn brings the handle back
        assertEquals(0, club.flips(ScriptedLoops.flight(180, true, target)));
        assertEquals(1, club.flips(ScriptedLoops.flight(320, true, target)));
        assertEquals(2, club.flips(ScriptedLoops.flight(720, true, target)));
        assertEquals(0, can.flips(new LoopRecord(0, true, Double.NaN, null, Double.NaN, null, false, Double.NaN, Double.NaN,
                Double.NaN, Double.NaN, Double.NaN, null, Double.NaN, 0, 0, 0, 1)), "the throw-in is no flip");
    }

    @Test
    void rewardFollowsEquation7() {
        Vec3 off = target.plus(new Vec3(0.05, 0, 0));
        // flipped and caught 5 cm from p_d: exp(-10 * 0.05) + r_flip
        assertEquals(Math.exp(-0.5) + 1, can.reward(ScriptedLoops.flight(180, true, off)), 1e-12);
        assertTrue(can.success(ScriptedLoops.flight(180, true, off)));
        // caught without a flip: the miss term, -0.1 |p_p - p_d|
        assertEquals(-0.1 * 0.05, can.reward(ScriptedLoops.flight(20, true, off)), 1e-12);
        assertFalse(can.success(ScriptedLoops.flight(20, true, off)));
        // flipped but dropped 1 m away
        Vec3 ground = target.plus(new Vec3(0, 0, 1));
        assertEquals(-0.1 * 1, can.reward(ScriptedLoops.flight(200, false, ground)), 1e-12);
    }

    @Test
    void aFlipCountsOnlyWhenTheObjectIsCaughtLyingInTheHand() {
        // configs/tasks/flip.json: the long axis at most 45 deg out of the palm's plane (a flip is caught "aligned with the palm")
        assertTrue(can.success(ScriptedLoops.flight(180, true, target, 0)), "lying flat in the palm");
        assertTrue(can.success(ScriptedLoops.flight(180, true, target, 44)), "1 deg inside the tilt allowed");
        assertFalse(can.success(ScriptedLoops.flight(180, true, target, 46)), "1 deg past it: leaning on the fingers");
        assertFalse(can.success(ScriptedLoops.flight(180, true, target, 85)), "standing on end in the palm");
        assertTrue(can.properCatch(ScriptedLoops.flight(20, true, target, 30)), "a catch without a flip can still be proper");
        assertFalse(can.properCatch(ScriptedLoops.flight(180, false, target)), "a drop is no catch");
        // eq. (7): a flip caught standing scores as a miss, -0.1 |p_p - p_d|
        Vec3 off = target.plus(new Vec3(0.05, 0, 0));
        assertEquals(-0.1 * 0.05, can.reward(ScriptedLoops.flight(180, true, off, 80)), 1e-12);
    }

    @Test
    void anObjectTheConfigDoesNotListIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> TestSupport.configs().flip().newTask("sphere"));
        assertTrue(e.getMessage().contains("sphere") && e.getMessage().contains("can"), e.getMessage());
    }

    @Test
    void onlyEndOverEndTurningCounts() {
        Vec3 up = Vec3.Y;
        double step = Math.toRadians(10);
        // a can lying along x tipped up about the horizontal z axis by 10 deg: all of it counts
        Vec3 tipped = new Vec3(Math.cos(step), Math.sin(step), 0);
        assertEquals(step, EndOverEnd.net(EndOverEnd.step(Vec3.X, tipped), up), 1e-12);
        // the same turn flat, about the vertical (a propeller spin): nothing counts
        Vec3 spun = new Vec3(Math.cos(step), 0, Math.sin(step));
        assertEquals(0, EndOverEnd.net(EndOverEnd.step(Vec3.X, spun), up), 1e-12);
        // about an axis 60 deg from the vertical: the turn times sin 60 deg (the horizontal part)
        Vec3 n = new Vec3(0, Math.cos(Math.toRadians(60)), Math.sin(Math.toRadians(60)));
        Vec3 between = handsim.math.Quat.fromAxisAngle(n, step).rotate(Vec3.X);
        assertEquals(step * Math.sin(Math.toRadians(60)), EndOverEnd.net(EndOverEnd.step(Vec3.X, between), up), 1e-9);
        // a turn and its way back cancel: the count is net, not a path length
        Vec3 there = EndOverEnd.step(Vec3.X, tipped), back = EndOverEnd.step(tipped, Vec3.X);
        assertEquals(0, EndOverEnd.net(there.plus(back), up), 1e-12);
        // the same weighting for rates: 5 rad/s about the horizontal z turns the x axis end over end
        // at 5 rad/s; about the vertical or about the axis itself not at all; about n, 5 sin 60 deg
        assertEquals(5, EndOverEnd.rate(new Vec3(0, 0, 5), Vec3.X, up), 1e-12);
        assertEquals(0, EndOverEnd.rate(new Vec3(0, 5, 0), Vec3.X, up), 1e-12);
        assertEquals(0, EndOverEnd.rate(new Vec3(5, 0, 0), Vec3.X, up), 1e-12);
        assertEquals(5 * Math.sin(Math.toRadians(60)), EndOverEnd.rate(n.times(5), Vec3.X, up), 1e-9);
    }

    /** The controller period: the episode shows the tracker one observation per 2 ms (configs/controller.json). */
    private static final double TICK = 0.002;

    /**
     * The net end-over-end turn a {@link FlightTracker} counts for a scripted flight: released at
     * t = 0 with the long axis at {@code axisAt.apply(0)}, followed every tick for {@code seconds}.
     */
    private static double trackedTurn(java.util.function.DoubleFunction<Vec3> axisAt, double seconds) {
        FlightTracker f = new FlightTracker(Vec3.Y);
        Vec3 rising = new Vec3(0, 2, 0);
        f.observe(true, true, Vec3.ZERO, rising, axisAt.apply(0), Vec3.ZERO); // held as the throw begins
        int ticks = (int) Math.round(seconds / TICK);
        for (int k = 0; k <= ticks; k++) {
            f.observe(false, true, Vec3.ZERO, rising, axisAt.apply(k * TICK), Vec3.ZERO);
        }
        return f.rotation();
    }

    @Test
    void aWobbleIsNoFlip() {
        // the long axis 30 deg above the horizontal, swept round the vertical at 3 rev/s for 0.6 s:
        // 1.8 sweeps of a tilted axis. Summed as a path (each tick's turn weighted by how
        // horizontal its axis is) it reads 281 deg, a can flip; the net turn about a horizontal axis
        // is sin(2e) |sin(pi n)| = sin 60 deg sin(0.2 pi) = 0.509 rad (29 deg) for e = 30 deg and
        // n = 1.8 sweeps (the horizontal turn axis sweeps round with the axis and cancels itself)
        double e = Math.toRadians(30), rate = 3 * 2 * Math.PI;
        double turn = trackedTurn(t -> new Vec3(Math.cos(e) * Math.cos(rate * t), Math.sin(e), Math.cos(e) * Math.sin(rate * t)), 0.6);
        assertEquals(Math.sin(2 * e) * Math.abs(Math.sin(Math.PI * 1.8)), turn, 0.01, "the closed form, to the ticks' chord error");
        assertEquals(0, can.flips(ScriptedLoops.flight(Math.toDegrees(turn), true, target)), "a wobble is no can flip");
        assertEquals(0, club.flips(ScriptedLoops.flight(Math.toDegrees(turn), true, target)));
    }

    @Test
    void aFlatSpinIsNoFlip() {
        // the long axis horizontal, spun about the vertical like a propeller at 20 rad/s for 0.6 s (nearly 2 turns)
        double turn = trackedTurn(t -> new Vec3(Math.cos(20 * t), 0, Math.sin(20 * t)), 0.6);
        assertEquals(0, turn, 1e-9, "every tick turns about the vertical");
        assertEquals(0, can.flips(ScriptedLoops.flight(Math.toDegrees(turn), true, target)));
    }

    @Test
    void aCleanHalfTurnIsOneCanFlip() {
        // end over end about the horizontal z axis at pi / 0.5 s: half a turn in 0.5 s of flight
        double turn = trackedTurn(t -> rotatedAboutZ(Math.PI * t / 0.5), 0.5);
        assertEquals(Math.PI, turn, 1e-9);
        assertEquals(1, can.flips(ScriptedLoops.flight(Math.toDegrees(turn), true, target)), "end for end is the same can");
        assertEquals(0, club.flips(ScriptedLoops.flight(Math.toDegrees(turn), true, target)), "the club's handle points away");
    }

    @Test
    void aCleanWholeTurnIsOneClubFlip() {
        // end over end about a horizontal axis 40 deg off z (any horizontal axis counts alike): a whole turn in 0.6 s
        Vec3 axis = new Vec3(Math.sin(Math.toRadians(40)), 0, Math.cos(Math.toRadians(40)));
        Vec3 start = axis.cross(Vec3.Y); // horizontal, square to the turn axis
        double turn = trackedTurn(t -> handsim.math.Quat.fromAxisAngle(axis, 2 * Math.PI * t / 0.6).rotate(start), 0.6);
        assertEquals(2 * Math.PI, turn, 1e-9);
        assertEquals(1, club.flips(ScriptedLoops.flight(Math.toDegrees(turn), true, target)), "the handle comes back to the hand");
        assertEquals(2, can.flips(ScriptedLoops.flight(Math.toDegrees(turn), true, target)), "two half turns of a can");
    }

    @Test
    void theFlightRunsFromTheLastTouchOnTheWayUpToTheFirstOnTheWayDown() {
        FlightTracker f = new FlightTracker(Vec3.Y);
        Vec3 rising = new Vec3(0, 2, 0), falling = new Vec3(0, -2, 0), p = Vec3.ZERO;
        double step = Math.toRadians(10);
        Vec3 spin = new Vec3(0, 0, 12); // 12 rad/s about the horizontal z axis: end over end
        f.reset();
        f.observe(true, false, p, rising, rotatedAboutZ(0), spin); // held, throw not begun
        f.observe(false, false, p, rising, rotatedAboutZ(0), spin); // no contact for a tick before the throw: no release
        assertEquals(0, f.rotation(), 0);
        assertTrue(Double.isNaN(f.releaseSpin()), "no release yet");
        // released, turns 30 deg, then the rising hand meets it again: that turn was part of the throw
        for (int k = 0; k <= 3; k++) {
            f.observe(false, true, p, rising, rotatedAboutZ(k * step), spin);
        }
        assertEquals(3 * step, f.rotation(), 1e-9);
        assertEquals(12, f.releaseSpin(), 1e-9, "the spin as it left the hand");
        f.observe(true, true, p, rising, rotatedAboutZ(3 * step), spin);
        assertEquals(null, f.catchPoint(), "a touch on the way up is no catch");
        // released again: 18 ticks of 10 deg (a half turn), over the apex, caught on the way down
        for (int k = 3; k <= 21; k++) {
            f.observe(false, true, p, k < 12 ? rising : falling, rotatedAboutZ(k * step), spin.times(0.75));
        }
        assertEquals(9, f.releaseSpin(), 1e-9, "the spin of the last release");
        Vec3 caughtAt = new Vec3(0, 0.8, 0.3);
        f.observe(true, true, caughtAt, falling, rotatedAboutZ(21 * step), spin);
        assertEquals(Math.PI, f.rotation(), 1e-9, "only the turn since the last release counts");
        assertEquals(caughtAt, f.catchPoint());
        // the axis at 210 deg from the horizontal x stands 30 deg out of the horizontal as it arrives
        assertEquals(Math.toRadians(30), f.arrivalTilt(), 1e-9);
        // after the catch nothing more is counted
        f.observe(false, true, p, falling, rotatedAboutZ(30 * step), spin);
        assertEquals(Math.PI, f.rotation(), 1e-9);
        assertEquals(Math.toRadians(30), f.arrivalTilt(), 1e-9, "the first touch only");
        f.reset();
        assertTrue(Double.isNaN(f.arrivalTilt()), "a new throw has not arrived");
    }

    private static Vec3 rotatedAboutZ(double angle) {
        return new Vec3(Math.cos(angle), Math.sin(angle), 0);
    }

    @Test
    void aClosedLoopReleaseIsSetPerObjectAndABadOneIsNamed() throws Exception {
        ControllerConfig base = ControllerConfig.load(Home.resolve("configs/controller.json"));
        assertTrue(can.controller(base).release().isEmpty(), "the shipped flip config lets go on time, as the paper");
        ObjectNode root = (ObjectNode) Json.mapper().readTree(Files.readString(Home.resolve("configs/tasks/flip.json")));
        ObjectNode release = ((ObjectNode) root.at("/objects/can")).putObject("release");
        release.put("predictedTurnDeg", 270).put("earliest", 0.15).put("extension", 0.04);
        FlipTask withRelease = new FlipTask(FlipTask.Config.parse(Json.of("flip.json", root)), "can", TestSupport.neutralPalm());
        ClosedLoopRelease r = withRelease.controller(base).release().orElseThrow();
        assertEquals(new ClosedLoopRelease(Math.toRadians(270), 0.15, 0.04), r);
        assertTrue(new FlipTask(FlipTask.Config.parse(Json.of("flip.json", root)), "club", TestSupport.neutralPalm())
                .controller(base).release().isEmpty(), "per object: the club has none");
        release.put("predictedTurnDeg", 0);
        ConfigException e = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(e.getMessage().contains("predictedTurnDeg"), e.getMessage());
        release.put("predictedTurnDeg", 270).put("earliest", 0.5); // THROW lasts 0.2 s
        FlipTask late = new FlipTask(FlipTask.Config.parse(Json.of("flip.json", root)), "can", TestSupport.neutralPalm());
        IllegalArgumentException tooLate = assertThrows(IllegalArgumentException.class, () -> late.controller(base));
        assertTrue(tooLate.getMessage().contains("earliest"), tooLate.getMessage());
    }

    @Test
    void anArmRestIsSetPerObjectAndABadOneIsNamed() throws Exception {
        ControllerConfig base = ControllerConfig.load(Home.resolve("configs/controller.json"));
        ArmRest rest = can.controller(base).armRest().orElseThrow();
        assertEquals(0.01, rest.gain(), "configs/tasks/flip.json objects.can.armRest");
        assertEquals(java.util.Set.of(Phase.GOBACK, Phase.MIDDLE), rest.phases(), "drawn while the arm goes back and holds the can");
        assertEquals(-21.4, rest.jointsDeg().get("shoulder_abduction"), 1e-12);
        double[] posture = rest.chainVector(TestSupport.model(), new int[] {0, 1, 2, 3, 4, 5, 6});
        assertEquals(Math.toRadians(-21.4), posture[1], 1e-12, "shoulder_abduction is the chain's second DOF");
        assertEquals(Math.toRadians(-26.0), posture[6], 1e-12, "wrist_deviation its last");
        java.util.Map<String, Double> reversed = new java.util.LinkedHashMap<>();
        new java.util.ArrayDeque<>(rest.jointsDeg().keySet()).descendingIterator().forEachRemaining(k -> reversed.put(k, rest.jointsDeg().get(k)));
        assertArrayEquals(posture, new ArmRest(reversed, rest.gain(), rest.phases()).chainVector(TestSupport.model(), new int[] {0, 1, 2, 3, 4, 5, 6}),
                "in the chain's order whatever the file's");
        assertEquals(ArmRest.parse(Json.of("saved", rest.toJson())), rest, "toJson gives it back");
        assertTrue(new FlipTask(FlipTask.Config.parse(Json.load(Home.resolve("configs/tasks/flip.json"))), "club",
                TestSupport.neutralPalm()).controller(base).armRest().isEmpty(), "per object: the club has none");

        ObjectNode root = (ObjectNode) Json.mapper().readTree(Files.readString(Home.resolve("configs/tasks/flip.json")));
        ObjectNode armRest = (ObjectNode) root.at("/objects/can/armRest");
        armRest.put("gain", 0);
        ConfigException badGain = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(badGain.getMessage().contains("gain") && badGain.getMessage().contains("got 0"), badGain.getMessage());
        armRest.put("gain", 0.01);
        ((com.fasterxml.jackson.databind.node.ArrayNode) armRest.get("phases")).add("BREAK");
        ConfigException badPhase = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(badPhase.getMessage().contains("phases") && badPhase.getMessage().contains("BREAK"), badPhase.getMessage());
        armRest.putArray("phases");
        ConfigException noPhase = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(noPhase.getMessage().contains("phases"), noPhase.getMessage());
        armRest.putArray("phases").add("GOBACK");
        ObjectNode joints = (ObjectNode) armRest.get("jointsDeg");
        int[] chain = {0, 1, 2, 3, 4, 5, 6};
        joints.put("index_mcp_flexion", 10); // a finger's DOF is not the arm's
        ArmRest finger = ArmRest.parse(Json.of("flip.json", armRest));
        IllegalArgumentException notChain = assertThrows(IllegalArgumentException.class,
                () -> finger.chainVector(TestSupport.model(), chain));
        assertTrue(notChain.getMessage().contains("index_mcp_flexion"), notChain.getMessage());
        joints.remove("index_mcp_flexion");
        joints.remove("wrist_deviation");
        ArmRest missing = ArmRest.parse(Json.of("flip.json", armRest));
        IllegalArgumentException lacks = assertThrows(IllegalArgumentException.class,
                () -> missing.chainVector(TestSupport.model(), chain));
        assertTrue(lacks.getMessage().contains("wrist_deviation"), lacks.getMessage());
        joints.put("wrist_deviation", -40); // the model's range is [-30, 20]
        ArmRest beyond = ArmRest.parse(Json.of("flip.json", armRest));
        IllegalArgumentException outside = assertThrows(IllegalArgumentException.class,
                () -> beyond.chainVector(TestSupport.model(), chain));
        assertTrue(outside.getMessage().contains("wrist_deviation") && outside.getMessage().contains("-40"), outside.getMessage());
    }

    @Test
    void aCatchAfterEachFlipIsSetPerObjectAndABadOneIsNamed() throws Exception {
        ControllerConfig base = ControllerConfig.load(Home.resolve("configs/controller.json"));
        // the shipped can is caught level and turned (configs/tasks/flip.json), the club as the controller catches
        assertEquals(new CatchStyle(0, 0.7, new CatchStyle.Level(0.15, 0, 0.01, Math.toRadians(15), Math.toRadians(143),
                Math.toRadians(25)), new Vec3(0, 0, -0.0075)), can.controller(base).catchAfterThrow().orElseThrow());
        ObjectNode root = (ObjectNode) Json.mapper().readTree(Files.readString(Home.resolve("configs/tasks/flip.json")));
        ObjectNode level = ((ObjectNode) root.at("/objects/can/catch/level")).put("step", 0);
        ConfigException badLevel = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(badLevel.getMessage().contains("step") && badLevel.getMessage().contains("0"), badLevel.getMessage());
        level.put("step", 0.01).put("minTurnDeg", -10);
        ConfigException badTurn = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(badTurn.getMessage().contains("minTurnDeg") && badTurn.getMessage().contains("-10"), badTurn.getMessage());
        level.put("minTurnDeg", 140).put("turnTiltDeg", 10); // less than tiltDeg 15
        ConfigException badTurnTilt = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(badTurnTilt.getMessage().contains("turnTiltDeg") && badTurnTilt.getMessage().contains("10"),
                badTurnTilt.getMessage());
        level.remove("minTurnDeg");
        level.put("turnTiltDeg", 25); // without the turn it goes with
        ConfigException lone = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(lone.getMessage().contains("turnTiltDeg") && lone.getMessage().contains("minTurnDeg"), lone.getMessage());
        level.put("minTurnDeg", 143);
        ((ObjectNode) root.at("/objects/can/catch")).putArray("offset").add(0).add(0).add(-0.05);
        ConfigException badOffset = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(badOffset.getMessage().contains("offset") && badOffset.getMessage().contains("0.05"), badOffset.getMessage());
        ((ObjectNode) root.at("/objects/can")).putObject("catch").put("planeShift", 0.1).put("velocityFraction", 0.45);
        ControllerConfig flipping = new FlipTask(FlipTask.Config.parse(Json.of("flip.json", root)), "can", TestSupport.neutralPalm())
                .controller(base);
        assertEquals(new CatchStyle(0.1, 0.45), flipping.catchAfterThrow().orElseThrow());
        assertEquals(base.catchStyle(), flipping.catchStyle(), "the throw-in is still caught as the controller's own");
        ((ObjectNode) root.at("/objects/can/catch")).put("velocityFraction", 1.5);
        ConfigException e = assertThrows(ConfigException.class, () -> FlipTask.Config.parse(Json.of("flip.json", root)));
        assertTrue(e.getMessage().contains("velocityFraction") && e.getMessage().contains("1.5"), e.getMessage());
    }

    /**
     * The rest read from a decision's observation: the long axis's tilt out of the palm's plane
     * (palm y: its normal) and heading from across it (palm z), in a palm turned 30 deg about its
     * normal so that the palm's frame, not the world's, decides; the thresholds are Rest.FLAT_TILT and
     * ASKEW_HEADING.
     */
    @Test
    void theRestAtADecisionIsReadInThePalmsFrame() {
        handsim.math.Quat palmTurn = handsim.math.Quat.fromAxisAngle(new Vec3(0, 1, 0), Math.toRadians(30));
        handsim.kin.Frame palm = new handsim.kin.Frame(Vec3.ZERO, palmTurn);
        Vec3 longAxis = new Vec3(0, 0, 1); // the can's, in its own frame
        Rest[] expected = {Rest.FLAT_ACROSS, Rest.FLAT_ASKEW, Rest.RAISED_ACROSS,
                Rest.RAISED_ASKEW};
        double[][] tiltHeadingDeg = {{3, 2}, {3, 20}, {25, 2}, {25, 20}};
        for (int i = 0; i < expected.length; i++) {
            double tilt = Math.toRadians(tiltHeadingDeg[i][0]), heading = Math.toRadians(tiltHeadingDeg[i][1]);
            // in the palm: x toward the fingers, y its normal, z across it
            Vec3 inPalm = new Vec3(Math.cos(tilt) * Math.sin(heading), Math.sin(tilt), Math.cos(tilt) * Math.cos(heading));
            handsim.math.Quat can = handsim.math.Quat.between(longAxis, palmTurn.rotate(inPalm));
            handsim.control.Observation at = new handsim.control.Observation(0, new double[0], new double[0], palm, Vec3.ZERO,
                    new handsim.sim.RigidState(Vec3.ZERO, can, Vec3.ZERO, Vec3.ZERO), 0);
            LyingPose pose = LyingPose.of(palm, can.rotate(longAxis));
            assertEquals(tilt, pose.tilt(), 1e-9, "tilt " + i);
            assertEquals(heading, pose.heading(), 1e-9, "heading " + i);
            assertEquals(expected[i], Rest.at(at, longAxis), "rest " + i);
        }
        assertEquals(Rest.FLAT_ASKEW, Rest.ofLabel("flat_askew"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Rest.ofLabel("flat"));
        assertTrue(e.getMessage().contains("\"flat\"") && e.getMessage().contains("flat_askew"), e.getMessage());
    }
}
