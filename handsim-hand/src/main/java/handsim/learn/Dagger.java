package handsim.learn;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;

/**
 * DAgger (Ross, Gordon and Bagnell 2011) with a teacher that answers the learner's own proposal:
 * each round plays episodes with the current learner, asks the teacher at every decision it
 * visits ({@link TeachableEnv#label}: the proposal is its own label when it succeeds, else the
 * nearest action the teacher finds to succeed), goes on with the label or the learner's action
 * ({@link DaggerConfig#executeLabel}), adds the labels to all earlier ones and fits a fresh actor
 * to the whole set by regression. The share of decisions where the learner's own action
 * succeeded is the round's measure of the learner, on the states it reaches.
 *
 * <p>Reproducible: a round's episodes, their teachers' searches and its fit are seeded from the
 * root seed and the round alone, so a round gives the same result however its episodes are
 * spread over workers or resumed.
 */
public final class Dagger {

    /** One episode to play: its round and index, the environment's seed, the teacher's and the cut-off. */
    public record Request(int round, int episode, long envSeed, long labelSeed, int maxDecisions, boolean executeLabel) {
    }

    /** A decision visited: the observation, the learner's proposal and the teacher's answer. */
    public record Visit(double[] observation, double[] proposal, Demonstration label) {

        public Visit {
            observation = observation.clone();
            proposal = proposal.clone();
        }
    }

    /** A played episode: its request and the decisions it visited, in order. */
    public record Episode(Request request, List<Visit> visits) {

        public Episode {
            visits = List.copyOf(visits);
        }
    }

    /** Plays a round's requests with one actor (on threads, worker processes, ...) and returns them in request order. */
    @FunctionalInterface
    public interface RoundPlayer {
        List<Episode> play(Function<double[], double[]> actor, List<Request> requests);
    }

    /**
     * What a round did.
     *
     * @param decisions decisions visited
     * @param proposalSuccesses of them, where the learner's own action succeeded
     * @param labelled where the teacher found an action that works (the proposal included)
     * @param tries the teacher's trials
     * @param examples labels in the fit after the round (all rounds so far, those kept by minRobustness)
     * @param trainLoss, validationLoss mean squared error per action entry of the fitted actor at its last epoch
     */
    public record RoundStats(int round, int episodes, int decisions, int proposalSuccesses, int labelled, long tries, int examples,
            double trainLoss, double validationLoss) {

        /** The learner's success: the share of its decisions where its own action succeeded (NaN for none). */
        public double proposalSuccessRate() {
            return decisions == 0 ? Double.NaN : (double) proposalSuccesses / decisions;
        }
    }

    /** A finished round: its episodes, its figures and the actor fitted after it. */
    public record Round(List<Episode> episodes, RoundStats stats, Policy policy) {
    }

    private final DaggerConfig config;
    private final int observationSize;
    private final int actionSize;

    public Dagger(DaggerConfig config, int observationSize, int actionSize) {
        this.config = config;
        this.observationSize = observationSize;
        this.actionSize = actionSize;
    }

    public DaggerConfig config() {
        return config;
    }

    /** Round {@code round}'s episodes, seeded from the root seed and the round. */
    public List<Request> requests(int round) {
        Rng rng = roundRng(round);
        List<Request> out = new ArrayList<>();
        for (int i = 0; i < config.episodesPerRound(); i++) {
            out.add(new Request(round, i, rng.nextLong(), rng.nextLong(), config.maxDecisionsPerEpisode(), config.executeLabel()));
        }
        return out;
    }

    /** The seed of round {@code round}'s fit (drawn after its episodes' seeds). */
    long fitSeed(int round) {
        Rng rng = roundRng(round);
        for (int i = 0; i < 2 * config.episodesPerRound(); i++) {
            rng.nextLong();
        }
        return rng.nextLong();
    }

    private Rng roundRng(int round) {
        Rng root = new Rng(config.seed());
        long s = root.nextLong();
        for (int r = 0; r < round; r++) {
            s = root.nextLong();
        }
        return new Rng(s);
    }

    /**
     * Plays one episode on {@code env}: at each decision the actor proposes (clipped to [-1, 1]),
     * the teacher labels, and the episode goes on with the label (when the request says so and the
     * teacher found one) or the proposal, until the environment ends it or the cut-off (no
     * decision at all when the environment's reset finds none, {@link TeachableEnv#reset}).
     */
    public static Episode play(TeachableEnv env, Request req, Function<double[], double[]> actor) {
        double[] obs = env.reset(req.envSeed());
        Rng labelSeeds = new Rng(req.labelSeed());
        List<Visit> visits = new ArrayList<>();
        for (int d = 0; obs != null && d < req.maxDecisions(); d++) {
            double[] proposal = clip(actor.apply(obs));
            Demonstration label = env.label(proposal, labelSeeds.nextLong());
            visits.add(new Visit(obs, proposal, label));
            Env.Step step = env.step(req.executeLabel() && label.labelled() ? label.action() : proposal);
            if (step.done()) {
                break;
            }
            obs = step.observation();
        }
        return new Episode(req, visits);
    }

    /**
     * Round {@code round}: its episodes played by {@code player} with {@code actor}, their labels
     * added to {@code earlier} (the visits of the rounds before), and an actor fitted to them all
     * ({@link #fit}; {@code network}: the actor when it is a network, else null).
     */
    public Round round(int round, Function<double[], double[]> actor, Policy network, RoundPlayer player, List<Visit> earlier) {
        List<Episode> episodes = player.play(actor, requests(round));
        List<Visit> all = new ArrayList<>(earlier);
        int decisions = 0, proposalSuccesses = 0, labelled = 0;
        long tries = 0;
        for (Episode e : episodes) {
            for (Visit v : e.visits()) {
                decisions++;
                proposalSuccesses += v.label().proposalSucceeded() ? 1 : 0;
                labelled += v.label().labelled() ? 1 : 0;
                tries += v.label().tries();
                all.add(v);
            }
        }
        Fit fit = fit(all, fitSeed(round), "DAgger round " + round, network);
        return new Round(episodes, new RoundStats(round, episodes.size(), decisions, proposalSuccesses, labelled, tries,
                fit.examples(), fit.trainLoss(), fit.validationLoss()), fit.policy());
    }

    /** A fitted actor and how well it fits. */
    public record Fit(Policy policy, int examples, double trainLoss, double validationLoss) {
    }

    /** A fit with fewer than two labels to fit to: the rounds gave the teacher too few decisions, or it found too few throws. */
    public static final class TooFewLabels extends IllegalStateException {
        private static final long serialVersionUID = 1L;

        TooFewLabels(String message) {
            super(message);
        }
    }

    /**
     * An actor ({@link DaggerConfig#network}, seeded by {@code seed}; with {@link
     * DaggerConfig.Refit#CONTINUE} starting as {@code start} when that is not null) fitted to the
     * labels of {@code visits} that the teacher found and that are robust enough ({@link
     * DaggerConfig#minRobustness}), weighted as the config says.
     */
    public Fit fit(List<Visit> visits, long seed, String note, Policy start) {
        List<Visit> kept = visits.stream().filter(v -> v.label().labelled() && v.label().robustness() >= config.minRobustness())
                .toList();
        if (kept.size() < 2) {
            throw new TooFewLabels("DAgger has " + kept.size() + " usable labels to fit (of " + visits.size() + " decisions): "
                    + (visits.size() < 2 ? "the episodes gave the learner too few decisions"
                            : "the teacher found too few throws that work (or too few robust enough)"));
        }
        double[][] obs = new double[kept.size()][], actions = new double[kept.size()][];
        double[] weights = new double[kept.size()];
        for (int i = 0; i < kept.size(); i++) {
            obs[i] = kept.get(i).observation();
            actions[i] = kept.get(i).label().action();
            weights[i] = config.weighting() == DaggerConfig.Weighting.ROBUSTNESS ? kept.get(i).label().robustness() : 1;
        }
        Rng seeds = new Rng(seed);
        DdpgAgent agent = DdpgAgent.create(config.network(), observationSize, actionSize, seeds.nextLong());
        if (start != null && config.refit() == DaggerConfig.Refit.CONTINUE) {
            agent.startActorFrom(start, config.fit().policyObservations());
        }
        ActorPretraining.Result r = ActorPretraining.fit(agent, obs, actions, weights, config.fit(), seeds.nextLong());
        int last = r.trainLoss().length - 1;
        return new Fit(agent.policy(note, "[-1, 1]^" + actionSize), kept.size(), r.trainLoss()[last], r.validationLoss()[last]);
    }

    private static double[] clip(double[] a) {
        double[] c = new double[a.length];
        for (int i = 0; i < a.length; i++) {
            c[i] = Math.max(-1, Math.min(1, a[i]));
        }
        return c;
    }
}
