package handsim.task;

import handsim.config.Json;
import handsim.control.ArmRest;
import handsim.control.CatchStyle;
import handsim.control.ClosedLoopRelease;
import handsim.control.ControllerConfig;
import handsim.control.Observation;
import handsim.control.ThrowParameters;
import handsim.control.ThrowSpace;
import handsim.math.Vec3;
import handsim.sim.ObjectSpec;
import handsim.sim.Simulator;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Predicate;
import java.util.function.ToIntFunction;

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
     * Throws whose angle (rad: the turn in flight, or the heading the object rested at before the
     * throw) lay between {@code from} and {@code to}, and how many of them were successes of the task.
     */
    public record AngleBin(double from, double to, int throwsMade, int successes) {
    }

    /**
     * The throws of {@code loops} (loop 0, the throw-in, and throws without a measured flight
     * left out) binned by their flight rotation in quarters of the flip angle, from 0 to the
     * largest, empty bins included: where a policy's throws fall against the window of rotations
     * that flip and come down lying in the hand.
     */
    public List<AngleBin> byFlightRotation(List<LoopRecord> loops) {
        double width = flip.flipAngle() / 4;
        List<LoopRecord> thrown = loops.stream().filter(l -> l.index() > 0 && Double.isFinite(l.flightRotation())).toList();
        int[] binOf = thrown.stream().mapToInt(l -> (int) (Math.max(0, l.flightRotation()) / width)).toArray();
        int bins = Arrays.stream(binOf).max().orElse(-1) + 1;
        int[] made = new int[bins], succeeded = new int[bins];
        for (int i = 0; i < binOf.length; i++) {
            made[binOf[i]]++;
            succeeded[binOf[i]] += success(thrown.get(i)) ? 1 : 0;
        }
        List<AngleBin> out = new ArrayList<>();
        for (int b = 0; b < bins; b++) {
            out.add(new AngleBin(b * width, (b + 1) * width, made[b], succeeded[b]));
        }
        return out;
    }

    /**
     * Throws whose object reached the hand again, by how far its long axis stood out of the
     * horizontal at that first touch ({@link LoopRecord#arrivalTilt}), and how they ended.
     *
     * @param from, to the bin's edges (rad)
     * @param standing caught, but not lying in the hand ({@link #properCatch})
     */
    public record ArrivalBin(double from, double to, int throwsMade, int successes, int drops, int standing) {
    }

    /**
     * The bins of a flip run's counts (configs/evaluation.json {@code flipBins}).
     *
     * @param angle width (rad) of the arrival-tilt and rest-heading bins, a whole share of 90 deg
     * @param earlyThrows throws 2 to this one are a loop's early throws, made while the rests settle
     * @param catchDistanceEdges rising edges (m) of the bins of {@link #laterThrowsByCatchDistance}
     */
    public record ReportBins(double angle, int earlyThrows, double[] catchDistanceEdges) {

        public ReportBins {
            catchDistanceEdges = catchDistanceEdges.clone();
        }

        @Override
        public double[] catchDistanceEdges() {
            return catchDistanceEdges.clone();
        }

        /** The angle bins from 0 to 90 deg. */
        int angleBins() {
            return (int) Math.round(Math.PI / 2 / angle);
        }
    }

    /**
     * The throws of {@code loops} that came back to the hand (loop 0 and throws without a first
     * touch left out) binned by their arrival tilt, all six bins from 0 to 90 deg: whether a
     * policy's failures are cans that arrive end-first (a wrong turn) or lying ones the catch lost.
     */
    public List<ArrivalBin> byArrivalTilt(List<LoopRecord> loops, ReportBins report) {
        double width = report.angle();
        int bins = report.angleBins();
        int[] made = new int[bins], succeeded = new int[bins], dropped = new int[bins], standing = new int[bins];
        for (LoopRecord l : loops) {
            if (l.index() == 0 || !Double.isFinite(l.arrivalTilt())) {
                continue;
            }
            int b = Math.min(bins - 1, (int) (l.arrivalTilt() / width));
            made[b]++;
            succeeded[b] += success(l) ? 1 : 0;
            dropped[b] += l.caught() ? 0 : 1;
            standing[b] += l.caught() && !properCatch(l) ? 1 : 0;
        }
        List<ArrivalBin> out = new ArrayList<>();
        for (int b = 0; b < bins; b++) {
            out.add(new ArrivalBin(b * width, (b + 1) * width, made[b], succeeded[b], dropped[b], standing[b]));
        }
        return out;
    }

    /**
     * Each episode's first throw (its loop 1) by the heading its caught throw-in came to rest at
     * ({@link LoopRecord#catchHeading}), all six bins from 0 to 90 deg: the arm cannot turn the
     * palm under every heading of the launched object, and one met askew rests askew.
     *
     * @param episodes each episode's loops, the throw-in first
     */
    public List<AngleBin> firstThrowsByRestHeading(List<List<LoopRecord>> episodes, ReportBins report) {
        double width = report.angle();
        int bins = report.angleBins();
        int[] made = new int[bins], succeeded = new int[bins];
        for (List<LoopRecord> loops : episodes) {
            if (loops.size() < 2 || !Double.isFinite(loops.get(0).catchHeading())) {
                continue;
            }
            int b = Math.min(bins - 1, (int) (loops.get(0).catchHeading() / width));
            made[b]++;
            succeeded[b] += success(loops.get(1)) ? 1 : 0;
        }
        List<AngleBin> out = new ArrayList<>();
        for (int b = 0; b < bins; b++) {
            out.add(new AngleBin(b * width, (b + 1) * width, made[b], succeeded[b]));
        }
        return out;
    }

    /** A rest less than this far out of the palm's plane lies flat (docs/experiments.md, What a throw fails from). */
    public static final double FLAT_REST = Math.toRadians(10);
    /** A rest this far or more from across the palm lies askew. */
    public static final double ASKEW_REST = Math.toRadians(5);

    /** How a long object lay in the hand when the catch before a throw was judged: raised or flat, across or askew. */
    public enum Rest {
        RAISED_ACROSS, RAISED_ASKEW, FLAT_ACROSS, FLAT_ASKEW;

        /** The rest of a catch's {@link LoopRecord#catchTilt} and {@link LoopRecord#catchHeading}. */
        public static Rest of(double tilt, double heading) {
            boolean flat = tilt < FLAT_REST, askew = heading >= ASKEW_REST;
            return flat ? (askew ? FLAT_ASKEW : FLAT_ACROSS) : (askew ? RAISED_ASKEW : RAISED_ACROSS);
        }

        /**
         * The rest of an object with long axis {@code longAxis} (body frame, unit) as {@code at}
         * sees it: at a throw's decision, made in the tick the catch is judged, the rest that
         * catch's {@link LoopRecord} records.
         */
        public static Rest at(Observation at, Vec3 longAxis) {
            LyingPose pose = LyingPose.of(at.palm(), at.object().orientation().rotate(longAxis));
            return of(pose.tilt(), pose.heading());
        }

        /** Which decisions find {@code object} resting this way ({@link #at}); refused for an object without a long axis. */
        public Predicate<Observation> decisionsOf(ObjectSpec object) {
            Vec3 axis = object.longAxis().orElseThrow(() -> new IllegalArgumentException("a " + object.name()
                    + " has no long axis to rest along"));
            return observation -> at(observation, axis) == this;
        }

        public String label() {
            return name().toLowerCase(Locale.ROOT);
        }

        /** The rest named by {@link #label}; an unknown name is refused with the names there are. */
        public static Rest ofLabel(String label) {
            for (Rest r : values()) {
                if (r.label().equals(label)) {
                    return r;
                }
            }
            throw new IllegalArgumentException("no rest \"" + label + "\" (one of " + Arrays.stream(values()).map(Rest::label).toList() + ")");
        }
    }

    /**
     * Throws made after some catches, early (throws 2 to {@link ReportBins#earlyThrows}) and from the next
     * one on, and how many of each were successes of the task.
     */
    public record ThrowsAfter(int earlyThrows, int earlySuccesses, int laterThrows, int laterSuccesses) {

        static final ThrowsAfter NONE = new ThrowsAfter(0, 0, 0, 0);

        ThrowsAfter plus(boolean early, boolean success) {
            int ok = success ? 1 : 0;
            return early ? new ThrowsAfter(earlyThrows + 1, earlySuccesses + ok, laterThrows, laterSuccesses)
                    : new ThrowsAfter(earlyThrows, earlySuccesses, laterThrows + 1, laterSuccesses + ok);
        }
    }

    /** The throws made from a {@code rest} left by the hand's own catch. */
    public record RestCount(Rest rest, ThrowsAfter throwsAfter) {
    }

    /**
     * The throws after each episode's first (from its second on) by how the catch before them
     * left the object ({@link Rest}), all four rests: where in the hand a policy throws badly
     * from. Throws after a catch with no measured tilt or heading are left out.
     *
     * @param episodes each episode's loops, the throw-in first
     */
    public List<RestCount> laterThrowsByRest(List<List<LoopRecord>> episodes, ReportBins report) {
        Rest[] rests = Rest.values();
        ThrowsAfter[] counts = countThrowsAfterCatches(episodes, report.earlyThrows(), rests.length, before ->
                !Double.isFinite(before.catchTilt()) || !Double.isFinite(before.catchHeading()) ? -1
                        : Rest.of(before.catchTilt(), before.catchHeading()).ordinal());
        return Arrays.stream(rests).map(r -> new RestCount(r, counts[r.ordinal()])).toList();
    }

    /**
     * The throws made after a catch that met the object {@code from} to {@code to} m
     * (horizontally) from the run's median catch ({@code to} infinite for the last bin).
     */
    public record DistanceCount(double from, double to, ThrowsAfter throwsAfter) {
    }

    /**
     * The throws after each episode's first by the horizontal distance of the catch before them
     * from {@code medianCatch}, where the run's catches meet the object (the median of each
     * coordinate of the hand's own catches; in a run of long loops, where its settled loops meet
     * it), in the bins of {@link ReportBins#catchDistanceEdges}.
     */
    public record CatchDistances(Vec3 medianCatch, List<DistanceCount> bins) {
    }

    /**
     * {@link CatchDistances} of some episodes: how far from where its catches usually meet the
     * object a catch must be to put the next throw at risk. Empty when no catch of the hand's own
     * (after a throw) met the object.
     *
     * @param episodes each episode's loops, the throw-in first
     */
    public Optional<CatchDistances> laterThrowsByCatchDistance(List<List<LoopRecord>> episodes, ReportBins report) {
        List<Vec3> catches = episodes.stream().flatMap(List::stream).filter(l -> l.index() >= 1 && l.catchPoint() != null)
                .map(LoopRecord::catchPoint).toList();
        if (catches.isEmpty()) {
            return Optional.empty();
        }
        Vec3 median = new Vec3(median(catches.stream().mapToDouble(Vec3::x).toArray()),
                median(catches.stream().mapToDouble(Vec3::y).toArray()), median(catches.stream().mapToDouble(Vec3::z).toArray()));
        double[] edges = report.catchDistanceEdges();
        ThrowsAfter[] counts = countThrowsAfterCatches(episodes, report.earlyThrows(), edges.length + 1, before -> {
            if (before.catchPoint() == null) {
                return -1;
            }
            double d = Math.hypot(before.catchPoint().x() - median.x(), before.catchPoint().z() - median.z());
            int b = 0;
            while (b < edges.length && d >= edges[b]) {
                b++;
            }
            return b;
        });
        List<DistanceCount> bins = new ArrayList<>();
        for (int b = 0; b <= edges.length; b++) {
            bins.add(new DistanceCount(b == 0 ? 0 : edges[b - 1], b == edges.length ? Double.POSITIVE_INFINITY : edges[b], counts[b]));
        }
        return Optional.of(new CatchDistances(median, bins));
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    }

    /**
     * The throws after each episode's first (from its second on), counted in {@code bins} bins by
     * the catch before them, early up to throw {@code earlyThrows}: {@code binOf} gives a catch's
     * bin, or -1 to leave the throw after it out.
     */
    private ThrowsAfter[] countThrowsAfterCatches(List<List<LoopRecord>> episodes, int earlyThrows, int bins,
            ToIntFunction<LoopRecord> binOf) {
        ThrowsAfter[] counts = new ThrowsAfter[bins];
        Arrays.fill(counts, ThrowsAfter.NONE);
        for (List<LoopRecord> loops : episodes) {
            for (int i = 2; i < loops.size(); i++) {
                int b = binOf.applyAsInt(loops.get(i - 1));
                if (b >= 0) {
                    counts[b] = counts[b].plus(i <= earlyThrows, success(loops.get(i)));
                }
            }
        }
        return counts;
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

    /**
     * The throws of some loops (the throw-in left out): how many were made, how many succeeded,
     * and how many failed for each {@link Failure} (every reason present, zeros included).
     */
    public record ThrowTally(int throwsMade, int successes, Map<Failure, Integer> failures) {

        public ThrowTally {
            failures = Map.copyOf(failures);
        }

        /** Successes per throw made (NaN for no throws). */
        public double successRate() {
            return throwsMade == 0 ? Double.NaN : (double) successes / throwsMade;
        }
    }

    /** How the throws of {@code loops} ended (loop 0, the throw-in, left out). */
    public ThrowTally tally(List<LoopRecord> loops) {
        Map<Failure, Integer> failures = new java.util.EnumMap<>(Failure.class);
        for (Failure f : Failure.values()) {
            failures.put(f, 0);
        }
        int made = 0, succeeded = 0;
        for (LoopRecord l : loops) {
            if (l.index() == 0) {
                continue;
            }
            made++;
            Optional<Failure> f = failure(l);
            if (f.isEmpty()) {
                succeeded++;
            } else {
                failures.merge(f.get(), 1, Integer::sum);
            }
        }
        return new ThrowTally(made, succeeded, failures);
    }

    /** Held in the hand and lying in it: the long axis at most maxCatchTilt out of the palm's plane. */
    public boolean properCatch(LoopRecord loop) {
        return loop.caught() && !(loop.catchTilt() > config.maxCatchTilt());
    }

    @Override
    public Goal drawing() {
        return new Goal.None();
    }

    @Override
    public String moveGoal(Vec3 delta) {
        return "the flip task has no goal to move";
    }
}
