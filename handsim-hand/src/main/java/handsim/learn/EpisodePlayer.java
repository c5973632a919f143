package handsim.learn;

import handsim.rollout.Rollouts;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;

/**
 * The learner's episode player: one episode with any actor (the live agent when learning
 * online), or a batch of episodes with a frozen {@link Policy} snapshot spread over the
 * environments of rollout workers ({@link handsim.rollout.Rollouts}, each worker owning one
 * environment). Given the {@link Env} contract (reset fully determines an episode), an episode
 * depends only on its request and the policy, so a batch's result is the same for any number of
 * workers and any scheduling; results come back in request order.
 */
public final class EpisodePlayer {

    /**
     * What to play.
     *
     * @param envSeed passed to {@link Env#reset}
     * @param noiseSeed seeds the episode's {@link ActionNoise}
     * @param sigma exploration noise scale (0: the actor's own action)
     * @param randomActions uniform random actions instead of the actor (warm-up)
     * @param maxDecisions the episode is cut off (truncated) after this many decisions
     */
    public record Request(long envSeed, long noiseSeed, double sigma, boolean randomActions, int maxDecisions) {
    }

    /** One decision: s, a, r, s', and whether s' is a real end (terminal; truncation is not). */
    public record Transition(double[] obs, double[] action, double reward, double[] nextObs, boolean terminal) {
    }

    /**
     * A played episode.
     *
     * @param firstObservation the observation after reset (for "Episode Q0")
     * @param terminal whether it ended by a real end rather than a cut-off
     */
    public record Episode(Request request, double[] firstObservation, List<Transition> transitions, double reward,
            boolean terminal) {
    }

    /** Sees an episode as it is played (online learning observes, stores and updates here). */
    @FunctionalInterface
    public interface StepHook {

        /** After every decision. */
        void afterStep(Transition t);

        /** After the reset, before the first decision. */
        default void onReset(double[] firstObservation) {
        }
    }

    private EpisodePlayer() {
    }

    /**
     * Plays one episode: reset with the request's seed, then act (the actor's action plus noise,
     * or random) until the task ends it or {@code maxDecisions} is reached (a truncation).
     */
    public static Episode play(Env env, Request req, Function<double[], double[]> actor,
            LearnerConfig.Exploration exploration, StepHook hook) {
        ActionNoise noise = new ActionNoise(exploration.noise(), exploration.ouTheta(), env.actionSize(), req.noiseSeed());
        double[] obs = env.reset(req.envSeed()).clone();
        double[] first = obs.clone();
        hook.onReset(first);
        List<Transition> transitions = new ArrayList<>();
        double total = 0;
        boolean terminal = false;
        for (int d = 0; d < req.maxDecisions(); d++) {
            double[] action = req.randomActions() ? noise.randomAction() : noise.perturb(actor.apply(obs), req.sigma());
            Env.Step step = env.step(action.clone());
            Transition t = new Transition(obs, action, step.reward(), step.observation().clone(), step.terminal());
            transitions.add(t);
            hook.afterStep(t);
            total += step.reward();
            obs = t.nextObs();
            if (step.done()) {
                terminal = step.terminal();
                break;
            }
        }
        return new Episode(req, first, List.copyOf(transitions), total, terminal);
    }

    /**
     * Plays the requests with one policy snapshot on the rollout workers' environments; results
     * in request order.
     */
    public static <E extends Env> List<Episode> playAll(Rollouts<E> envs, Policy policy, List<Request> requests,
            LearnerConfig.Exploration exploration) {
        return envs.run(requests.size(), env -> i -> play(env, requests.get(i), policy::act, exploration, t -> { }));
    }

    /** A trainer's rounds played on the rollout workers' environments ({@link #playAll}). */
    public static <E extends Env> Trainer.RoundPlayer onWorkers(Rollouts<E> envs, LearnerConfig.Exploration exploration) {
        return (snapshot, requests) -> playAll(envs, snapshot, requests, exploration);
    }
}
