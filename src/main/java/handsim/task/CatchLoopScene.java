package handsim.task;

import handsim.sim.Simulator;
import handsim.sim.WorldSnapshot;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Endless catch-and-throw for watching: runs the episodes of a {@link CatchEvaluation} one after
 * another. When an episode ends (a drop or a time limit) the world is reset and the next seed's
 * object is thrown in; the status says so, and the loop count starts again from zero.
 */
public final class CatchLoopScene implements Scene {

    private final Simulator sim;
    private final CatchEvaluation evaluation;
    private CatchThrowEpisode episode;
    private long seed;
    private int episodes;
    private String lastEvent = "thrown in";

    /** Owns {@code sim} (closed with the scene) and starts the episode of {@code seed}. */
    public CatchLoopScene(Simulator sim, CatchEvaluation evaluation, long seed) {
        this.sim = sim;
        this.evaluation = evaluation;
        this.seed = seed;
        this.episode = evaluation.start(sim, seed);
    }

    @Override
    public void advance(double seconds) {
        double until = sim.time() + seconds;
        while (sim.time() < until - 1e-12) {
            if (episode.status() != CatchThrowEpisode.Status.RUNNING) {
                lastEvent = episode.status() == CatchThrowEpisode.Status.DROPPED ? "dropped: new throw" : "time limit: new throw";
                episodes++;
                seed++;
                episode = evaluation.start(sim, seed);
                return;
            }
            LoopRecord r = episode.tick();
            if (r != null) {
                lastEvent = r.caught() ? (r.index() == 0 ? "caught" : String.format("caught, apex %.2f m", r.apexHeight())) : "dropped";
            }
        }
    }

    @Override
    public double time() {
        return sim.time();
    }

    @Override
    public WorldSnapshot snapshot() {
        return sim.snapshot();
    }

    /** The episode being run now. */
    public CatchThrowEpisode episode() {
        return episode;
    }

    @Override
    public Map<String, String> status() {
        Map<String, String> s = new LinkedHashMap<>();
        s.put("state", episode.state().phase().name());
        s.put("loops", Integer.toString(Math.max(0, episode.result(seed).loopsCompleted())));
        s.put("last", lastEvent);
        s.put("seed", Long.toString(seed));
        s.put("episodes", Integer.toString(episodes));
        s.put("t", String.format("%.2f s", sim.time()));
        return s;
    }

    @Override
    public void close() {
        sim.close();
    }
}
