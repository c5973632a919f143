package handsim.evaluation;

import handsim.math.Vec3;
import handsim.task.FlipTask;
import handsim.task.LoopRecord;
import handsim.task.Rest;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.ToIntFunction;

/**
 * The counts of a flip run's report: how its throws ended ({@link #tally}), by flight rotation,
 * by arrival tilt, first throws by the heading the throw-in came to rest at, and later throws by
 * the rest and by the catch distance before them, in the bins of configs/evaluation.json
 * {@code flipBins}. Success and failure are the flip task's ({@link FlipTask#success}, {@link
 * FlipTask#failure}).
 */
public final class FlipReport {

    private final FlipTask task;
    private final Bins binning;

    public FlipReport(FlipTask task, Bins bins) {
        this.task = task;
        this.binning = bins;
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
        double width = task.flipAngle() / 4;
        List<LoopRecord> thrown = loops.stream().filter(l -> l.index() > 0 && Double.isFinite(l.flightRotation())).toList();
        int[] binOf = thrown.stream().mapToInt(l -> (int) (Math.max(0, l.flightRotation()) / width)).toArray();
        int bins = Arrays.stream(binOf).max().orElse(-1) + 1;
        int[] made = new int[bins], succeeded = new int[bins];
        for (int i = 0; i < binOf.length; i++) {
            made[binOf[i]]++;
            succeeded[binOf[i]] += task.success(thrown.get(i)) ? 1 : 0;
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
    public record Bins(double angle, int earlyThrows, double[] catchDistanceEdges) {

        public Bins {
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
    public List<ArrivalBin> byArrivalTilt(List<LoopRecord> loops) {
        double width = binning.angle();
        int bins = binning.angleBins();
        int[] made = new int[bins], succeeded = new int[bins], dropped = new int[bins], standing = new int[bins];
        for (LoopRecord l : loops) {
            if (l.index() == 0 || !Double.isFinite(l.arrivalTilt())) {
                continue;
            }
            int b = Math.min(bins - 1, (int) (l.arrivalTilt() / width));
            made[b]++;
            succeeded[b] += task.success(l) ? 1 : 0;
            dropped[b] += l.caught() ? 0 : 1;
            standing[b] += l.caught() && !task.properCatch(l) ? 1 : 0;
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
    public List<AngleBin> firstThrowsByRestHeading(List<List<LoopRecord>> episodes) {
        double width = binning.angle();
        int bins = binning.angleBins();
        int[] made = new int[bins], succeeded = new int[bins];
        for (List<LoopRecord> loops : episodes) {
            if (loops.size() < 2 || !Double.isFinite(loops.get(0).catchHeading())) {
                continue;
            }
            int b = Math.min(bins - 1, (int) (loops.get(0).catchHeading() / width));
            made[b]++;
            succeeded[b] += task.success(loops.get(1)) ? 1 : 0;
        }
        List<AngleBin> out = new ArrayList<>();
        for (int b = 0; b < bins; b++) {
            out.add(new AngleBin(b * width, (b + 1) * width, made[b], succeeded[b]));
        }
        return out;
    }

    /**
     * Throws made after some catches, early (throws 2 to {@link Bins#earlyThrows}) and from the next
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
    public List<RestCount> laterThrowsByRest(List<List<LoopRecord>> episodes) {
        Rest[] rests = Rest.values();
        ThrowsAfter[] counts = countThrowsAfterCatches(episodes, binning.earlyThrows(), rests.length, before ->
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
     * it), in the bins of {@link Bins#catchDistanceEdges}.
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
    public Optional<CatchDistances> laterThrowsByCatchDistance(List<List<LoopRecord>> episodes) {
        List<Vec3> catches = episodes.stream().flatMap(List::stream).filter(l -> l.index() >= 1 && l.catchPoint() != null)
                .map(LoopRecord::catchPoint).toList();
        if (catches.isEmpty()) {
            return Optional.empty();
        }
        Vec3 median = new Vec3(median(catches.stream().mapToDouble(Vec3::x).toArray()),
                median(catches.stream().mapToDouble(Vec3::y).toArray()), median(catches.stream().mapToDouble(Vec3::z).toArray()));
        double[] edges = binning.catchDistanceEdges();
        ThrowsAfter[] counts = countThrowsAfterCatches(episodes, binning.earlyThrows(), edges.length + 1, before -> {
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
                    counts[b] = counts[b].plus(i <= earlyThrows, task.success(loops.get(i)));
                }
            }
        }
        return counts;
    }

    /**
     * The throws of some loops (the throw-in left out): how many were made, how many succeeded,
     * and how many failed for each {@link Failure} (every reason present, zeros included).
     */
    public record ThrowTally(int throwsMade, int successes, Map<FlipTask.Failure, Integer> failures) {

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
        Map<FlipTask.Failure, Integer> failures = new EnumMap<>(FlipTask.Failure.class);
        for (FlipTask.Failure f : FlipTask.Failure.values()) {
            failures.put(f, 0);
        }
        int made = 0, succeeded = 0;
        for (LoopRecord l : loops) {
            if (l.index() == 0) {
                continue;
            }
            made++;
            Optional<FlipTask.Failure> f = task.failure(l);
            if (f.isEmpty()) {
                succeeded++;
            } else {
                failures.merge(f.get(), 1, Integer::sum);
            }
        }
        return new ThrowTally(made, succeeded, failures);
    }
}
