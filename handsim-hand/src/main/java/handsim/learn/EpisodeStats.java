package handsim.learn;

/**
 * What one training episode reports (one row of {@code metrics.csv}; the curves of paper
 * Fig. 6, 9, 10).
 *
 * @param episode 1-based episode number of the run
 * @param totalSteps decisions of the run so far, this episode included
 * @param decisions decisions of this episode
 * @param reward sum of this episode's rewards
 * @param averageReward mean episode reward over the last movingAverageWindow episodes
 * @param q0 "Episode Q0": the critic's Q(s0, mu(s0)) at the episode's first observation, with
 *     the networks the episode was played with
 * @param criticLoss mean critic loss of the updates done for this episode (NaN if none)
 * @param actorLoss mean actor loss, -Q(s, mu(s)), of those updates (NaN if none)
 * @param updates gradient updates of the run so far
 * @param terminal whether the episode ended by a real end rather than a cut-off
 * @param sigma exploration noise scale of the episode (NaN for warm-up random actions)
 * @param wallSeconds wall time of the run so far, s
 */
public record EpisodeStats(long episode, long totalSteps, int decisions, double reward, double averageReward, double q0,
        double criticLoss, double actorLoss, long updates, boolean terminal, double sigma, double wallSeconds) {
}
