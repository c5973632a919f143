package handsim.task;

import java.util.List;

/**
 * The outcome of one catch-and-throw episode.
 *
 * @param seed the episode's seed (launch draw, object variation and engine)
 * @param loops the finished loops: loop 0 is the first catch, loop k the k-th throw and catch
 * @param status how the episode ended
 */
public record EpisodeResult(long seed, List<LoopRecord> loops, CatchThrowEpisode.Status status) {

    public EpisodeResult {
        loops = List.copyOf(loops);
    }

    public boolean firstCatch() {
        return !loops.isEmpty() && loops.get(0).caught();
    }

    /** Throws made (loops after the first catch). */
    public int loopsAttempted() {
        return Math.max(0, loops.size() - 1);
    }

    /** Consecutive catch-throw-catch cycles before the first drop. */
    public int loopsCompleted() {
        int n = 0;
        for (LoopRecord r : loops) {
            if (!r.caught()) {
                break;
            }
            n = r.index();
        }
        return n;
    }

    /** 1 if the episode ended with the object dropped, else 0. */
    public int drops() {
        return status == CatchThrowEpisode.Status.DROPPED ? 1 : 0;
    }

    /** 1 if the episode ended with a loop that ran out of time (configs/episode.json maxLoopSeconds), else 0. */
    public int timeOuts() {
        return status == CatchThrowEpisode.Status.TIME_LIMIT ? 1 : 0;
    }

    /** Largest joint-limit excursion of the episode (rad). */
    public double maxLimitExcess() {
        return loops.stream().mapToDouble(LoopRecord::maxLimitExcess).max().orElse(0);
    }

    /** Deepest hand-object penetration of the episode (m). */
    public double maxPenetration() {
        return loops.stream().mapToDouble(LoopRecord::maxPenetration).max().orElse(0);
    }

    public double peakTorqueRatio() {
        return loops.stream().mapToDouble(LoopRecord::peakTorqueRatio).max().orElse(0);
    }
}
