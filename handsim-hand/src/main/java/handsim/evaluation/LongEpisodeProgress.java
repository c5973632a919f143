package handsim.evaluation;

import handsim.task.LoopRecord;

import java.io.PrintStream;
import java.util.Locale;

/**
 * Progress of one long episode: every {@code every} loops a line with the loops made, the pace
 * and the time left until {@code maxLoops} at that pace (an episode that drops its object ends
 * sooner). One per episode; an episode shorter than {@code every} loops prints nothing.
 */
public final class LongEpisodeProgress implements CatchEvaluation.LoopListener {

    private final PrintStream out;
    private final int every;
    private final int maxLoops;
    private final long start = System.nanoTime();

    public LongEpisodeProgress(PrintStream out, int every, int maxLoops) {
        this.out = out;
        this.every = every;
        this.maxLoops = maxLoops;
    }

    @Override
    public void onLoop(long seed, LoopRecord loop) {
        int done = loop.index();
        if (done == 0 || done % every != 0 || done >= maxLoops) {
            return;
        }
        double seconds = (System.nanoTime() - start) * 1e-9;
        double perLoop = seconds / done;
        long left = Math.round(perLoop * (maxLoops - done));
        out.printf(Locale.ROOT, "episode %d: loop %d of at most %d, %.1f loops/min, about %d:%02d:%02d left%n", seed, done,
                maxLoops, 60 / perLoop, left / 3600, left / 60 % 60, left % 60);
    }
}
