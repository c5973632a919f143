package handsim.learn;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

/**
 * The DDPG training driver for any {@link Env}: warm-up episodes with random actions, then the
 * actor's action plus decaying noise; every decision stored in the replay buffer and followed
 * by {@code updatesPerStep} updates (DDPG, Alg. 1). With {@code parallelEpisodes} K > 1 it plays
 * K episodes at once with a frozen policy snapshot on several environment instances, then does
 * their updates. Episode bookkeeping goes to a {@link TrainingListener}.
 *
 * <p>Warm-up and noise scale are decided per episode from the decisions done when it starts.
 * Reproducible: one root seed fixes everything, and the run is the same whether it was
 * interrupted and resumed from a {@link #checkpoint} or not (wall time aside).
 */
public final class Trainer {

    /**
     * Plays a round's episode requests with a frozen policy snapshot and returns them in request
     * order (on rollout workers, {@link EpisodePlayer#onWorkers}, or however the caller runs them).
     */
    @FunctionalInterface
    public interface RoundPlayer {
        List<EpisodePlayer.Episode> play(Policy snapshot, List<EpisodePlayer.Request> requests);
    }

    private final LearnerConfig config;
    private final DdpgAgent agent;
    private final Rng episodeRng;
    private final ArrayDeque<Double> recentRewards = new ArrayDeque<>();
    private long episodes;
    private long steps;
    private final double elapsedBefore;
    private final long startNanos = System.nanoTime();
    private double criticLossSum; // over the updates since the last reported episode
    private double actorLossSum;
    private int lossCount;
    /** What the checkpoint this trainer was resumed from says it belongs to (null: none said, or not resumed). */
    private com.fasterxml.jackson.databind.JsonNode identity;

    private Trainer(LearnerConfig config, DdpgAgent agent, Rng episodeRng, double elapsedBefore) {
        this.config = config;
        this.agent = agent;
        this.episodeRng = episodeRng;
        this.elapsedBefore = elapsedBefore;
    }

    /**
     * A fresh run. Seeding: the root seed starts one generator; its first draw seeds the agent
     * (weights, replay sampling), its second the episodes (each episode draws its env and
     * noise seeds from it, in episode order).
     */
    public static Trainer create(LearnerConfig config, int obsSize, int actionSize) {
        Rng root = new Rng(config.seed());
        DdpgAgent agent = DdpgAgent.create(config.ddpg(), obsSize, actionSize, root.nextLong());
        return new Trainer(config, agent, new Rng(root.nextLong()), 0);
    }

    /** A run with a given agent (e.g. one whose actor was pretrained, {@link ActorPretraining}). */
    public static Trainer withAgent(LearnerConfig config, DdpgAgent agent) {
        if (!config.ddpg().equals(agent.config())) {
            throw new IllegalArgumentException("the agent was built with another ddpg section than the run's");
        }
        Rng root = new Rng(config.seed());
        root.nextLong();
        return new Trainer(config, agent, new Rng(root.nextLong()), 0);
    }

    /**
     * A run continued with {@code agent} after {@code episodes} episodes and {@code steps}
     * decisions (a run whose checkpoints were lost, from a saved actor): the episodes go on with
     * the seeds and noise an uninterrupted run gives them (the episode generator is drawn forward
     * past the episodes played), the noise at its scale for {@code steps}; {@code recentRewards}
     * (oldest first) seed the moving average. What the checkpoint held and the agent lacks (a
     * trained critic, the replay buffer) makes the rest of the run differ from the lost one.
     */
    public static Trainer continueFrom(LearnerConfig config, DdpgAgent agent, long episodes, long steps,
            List<Double> recentRewards, double elapsedSeconds) {
        Trainer t = withAgent(config, agent);
        Trainer fresh = new Trainer(config, agent, t.episodeRng, elapsedSeconds);
        for (long e = 0; e < episodes; e++) {
            fresh.nextRequest(); // each episode draws its env and noise seeds
        }
        fresh.episodes = episodes;
        fresh.steps = steps;
        recentRewards.forEach(fresh.recentRewards::addLast);
        while (fresh.recentRewards.size() > config.training().movingAverageWindow()) {
            fresh.recentRewards.removeFirst();
        }
        return fresh;
    }

    /** Continues a run from its checkpoint, with the configuration saved there. */
    public static Trainer resume(Path checkpoint) throws IOException {
        return resume(checkpoint, null);
    }

    /**
     * Continues a run from its checkpoint with another configuration (e.g. more episodes);
     * {@code null} keeps the saved one. The learner's section must be unchanged.
     */
    public static Trainer resume(Path checkpoint, LearnerConfig override) throws IOException {
        Checkpoints.Loaded loaded = Checkpoints.load(checkpoint);
        if (loaded.extra() == null) {
            throw new IOException(checkpoint + ": holds an agent but no trainer state");
        }
        Json s = Json.of(checkpoint + "!state.json:extra", loaded.extra());
        LearnerConfig saved = LearnerConfig.parse(s.get("config"));
        LearnerConfig config = override == null ? saved : override;
        if (!config.ddpg().equals(saved.ddpg())) {
            throw new IllegalArgumentException("the ddpg section differs from the one saved in " + checkpoint);
        }
        Trainer t = new Trainer(config, loaded.agent(), new Rng(s.longValue("episodeRng")), s.number("elapsedSeconds"));
        t.episodes = s.longValue("episodes");
        t.steps = s.longValue("steps");
        for (double r : s.numbers("recentRewards", -1)) {
            t.recentRewards.add(r);
        }
        t.identity = loaded.extra().get("identity");
        s.allow("identity");
        s.requireNoUnknownFields();
        return t;
    }

    /** This run going on under {@code other} (a larger budget, say); its ddpg section must be this run's. */
    public Trainer withConfig(LearnerConfig other) {
        if (!other.ddpg().equals(config.ddpg())) {
            throw new IllegalArgumentException("the ddpg section differs from the run's");
        }
        Trainer t = new Trainer(other, agent, episodeRng, elapsedSeconds());
        t.episodes = episodes;
        t.steps = steps;
        t.recentRewards.addAll(recentRewards);
        return t;
    }

    /** Saves the agent and this driver's state (atomically). Call between episodes. */
    public void checkpoint(Path file) throws IOException {
        checkpoint(file, null);
    }

    /**
     * {@link #checkpoint(Path)} with {@code identity} recorded in it: what run the checkpoint
     * belongs to (its task, object, config and run), which a resume compares with its own.
     */
    public void checkpoint(Path file, com.fasterxml.jackson.databind.JsonNode identity) throws IOException {
        ObjectNode s = Json.mapper().createObjectNode();
        if (identity != null) {
            s.set("identity", identity);
        }
        s.set("config", config.toJson());
        s.put("episodes", episodes);
        s.put("steps", steps);
        s.put("episodeRng", episodeRng.state());
        ArrayNode recent = s.putArray("recentRewards");
        recentRewards.forEach(recent::add);
        s.put("elapsedSeconds", elapsedSeconds());
        Checkpoints.save(file, agent, s);
    }

    public DdpgAgent agent() {
        return agent;
    }

    /** The identity the checkpoint this trainer was resumed from records ({@link #checkpoint(Path, com.fasterxml.jackson.databind.JsonNode)}), or null. */
    public com.fasterxml.jackson.databind.JsonNode identity() {
        return identity;
    }

    public LearnerConfig config() {
        return config;
    }

    /** Episodes played so far. */
    public long episodes() {
        return episodes;
    }

    /** Decisions taken so far. */
    public long steps() {
        return steps;
    }

    /**
     * Trains until {@code training.episodes} episodes are done, saving {@code checkpointFile}
     * (if not null) every {@code checkpointEveryEpisodes} episodes and at the end: online on
     * {@code env} when {@code parallelEpisodes} is 1, else in rounds played by {@code rounds}
     * (which may be null otherwise).
     */
    public void train(Env env, RoundPlayer rounds, TrainingListener listener, Path checkpointFile) throws IOException {
        int every = config.training().checkpointEveryEpisodes();
        while (episodes < config.training().episodes()) {
            long before = episodes;
            if (config.training().parallelEpisodes() == 1) {
                runEpisode(env, listener);
            } else {
                runRound(rounds, listener);
            }
            if (checkpointFile != null && every > 0 && episodes / every != before / every) {
                checkpoint(checkpointFile);
            }
        }
        if (checkpointFile != null) {
            checkpoint(checkpointFile);
        }
    }

    /** One episode of online learning: store and update after every decision. */
    public EpisodeStats runEpisode(Env env, TrainingListener listener) {
        EpisodePlayer.Request req = nextRequest();
        double[] q0 = {Double.NaN};
        EpisodePlayer.Episode ep = EpisodePlayer.play(env, req, agent::act, config.exploration(), new EpisodePlayer.StepHook() {
            @Override
            public void onReset(double[] first) {
                agent.observe(first);
                q0[0] = agent.value(first);
            }

            @Override
            public void afterStep(EpisodePlayer.Transition t) {
                learnFrom(t, listener);
            }
        });
        return finishEpisode(ep, q0[0], meanCriticLoss(), meanActorLoss(), steps, listener);
    }

    /**
     * {@code parallelEpisodes} episodes played at once with the current policy snapshot, then
     * their updates; results in episode order whatever the number of workers. The round's mean
     * losses are reported on each of its episodes.
     */
    public List<EpisodeStats> runRound(RoundPlayer player, TrainingListener listener) {
        return runRound(player, listener, Integer.MAX_VALUE);
    }

    /**
     * A round of at most {@code maxEpisodes} episodes (train --session-episodes stopping before
     * the run's budget). A round whose play throws (a stop request) changes nothing: a checkpoint
     * taken after it is the one the round would have started from.
     */
    public List<EpisodeStats> runRound(RoundPlayer player, TrainingListener listener, int maxEpisodes) {
        int k = (int) Math.min(Math.min(config.training().parallelEpisodes(), maxEpisodes),
                Math.max(1, config.training().episodes() - episodes));
        long drawnFrom = episodeRng.state();
        List<EpisodePlayer.Request> requests = new ArrayList<>();
        for (int i = 0; i < k; i++) {
            requests.add(nextRequest());
        }
        Policy snapshot = agent.policy("training snapshot", "[-1, 1]^" + agent.actionSize());
        List<EpisodePlayer.Episode> played;
        try {
            played = player.play(snapshot, requests);
        } catch (RuntimeException e) {
            // a round that did not finish (a stop request, a failure) leaves the learner as it was before it
            episodeRng.setState(drawnFrom);
            throw e;
        }
        double[] q0 = new double[k];
        for (int i = 0; i < k; i++) {
            q0[i] = agent.value(played.get(i).firstObservation()); // the networks the episodes were played with
        }
        long stepsAtEnd = steps;
        for (EpisodePlayer.Episode ep : played) {
            agent.observe(ep.firstObservation());
            for (EpisodePlayer.Transition t : ep.transitions()) {
                learnFrom(t, listener);
            }
        }
        double criticLoss = meanCriticLoss(), actorLoss = meanActorLoss();
        List<EpisodeStats> out = new ArrayList<>();
        for (int i = 0; i < k; i++) {
            stepsAtEnd += played.get(i).transitions().size();
            out.add(finishEpisode(played.get(i), q0[i], criticLoss, actorLoss, stepsAtEnd, listener));
        }
        return out;
    }

    private EpisodePlayer.Request nextRequest() {
        long envSeed = episodeRng.nextLong();
        long noiseSeed = episodeRng.nextLong();
        boolean warmup = steps < config.exploration().warmupSteps();
        return new EpisodePlayer.Request(envSeed, noiseSeed, config.exploration().sigmaAt(steps), warmup,
                config.training().maxDecisionsPerEpisode());
    }

    /** Store a decision; after the warm-up, do the updates it is worth. */
    private void learnFrom(EpisodePlayer.Transition t, TrainingListener listener) {
        agent.observe(t.nextObs());
        agent.store(t.obs(), t.action(), t.reward(), t.nextObs(), t.terminal());
        steps++;
        if (steps < config.exploration().warmupSteps() || !agent.canUpdate()) {
            return;
        }
        // critic warm-up: for its first decisions after the random warm-up only the critic learns
        boolean updateActor = steps >= config.exploration().warmupSteps() + config.training().criticWarmupDecisions();
        for (int u = 0; u < config.training().updatesPerStep(); u++) {
            DdpgAgent.Losses losses = agent.update(updateActor);
            criticLossSum += losses.critic();
            actorLossSum += losses.actor();
            lossCount++;
            listener.onUpdate(agent.updates(), losses);
        }
    }

    private double meanCriticLoss() {
        return lossCount == 0 ? Double.NaN : criticLossSum / lossCount;
    }

    private double meanActorLoss() {
        return lossCount == 0 ? Double.NaN : actorLossSum / lossCount;
    }

    private EpisodeStats finishEpisode(EpisodePlayer.Episode ep, double q0, double criticLoss, double actorLoss,
            long stepsAtEnd, TrainingListener listener) {
        episodes++;
        recentRewards.addLast(ep.reward());
        while (recentRewards.size() > config.training().movingAverageWindow()) {
            recentRewards.removeFirst();
        }
        double average = recentRewards.stream().mapToDouble(Double::doubleValue).average().orElse(Double.NaN);
        EpisodeStats stats = new EpisodeStats(episodes, stepsAtEnd, ep.transitions().size(), ep.reward(), average, q0,
                criticLoss, actorLoss, agent.updates(), ep.terminal(),
                ep.request().randomActions() ? Double.NaN : ep.request().sigma(), elapsedSeconds());
        criticLossSum = 0;
        actorLossSum = 0;
        lossCount = 0;
        listener.onEpisode(stats);
        return stats;
    }

    private double elapsedSeconds() {
        return elapsedBefore + (System.nanoTime() - startNanos) * 1e-9;
    }
}
