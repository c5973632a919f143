package handsim.learn;

/** Receives training progress (the app writes metrics.csv and curves from it). */
@FunctionalInterface
public interface TrainingListener {

    void onEpisode(EpisodeStats stats);

    /** After every gradient update; {@code update} is 1-based over the run. */
    default void onUpdate(long update, DdpgAgent.Losses losses) {
    }
}
