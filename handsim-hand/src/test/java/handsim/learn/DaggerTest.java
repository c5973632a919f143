package handsim.learn;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.config.Json;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * DAgger on a task without physics: the learner must find a narrow window of actions that
 * depends on the state, as a throw that flips must.
 */
@Tag("slow")
class DaggerTest {

    /**
     * Each decision sees a random state s in [-1, 1]^2; an action a in [-1, 1] succeeds when
     * |a - f(s)| <= 0.1, f(s) = 0.5 s0 + 0.3 s1. The teacher labels a failed proposal with
     * the nearest action 0.05 inside the window (labels on its very edge fit an actor that sits on
     * the edge and fails about half the time). A success goes on to a fresh state; a failure ends
     * the episode.
     */
    static class Window implements TeachableEnv {
        int labels;
        private Rng rng;
        private double[] s;

        static double best(double[] s) {
            return 0.5 * s[0] + 0.3 * s[1];
        }

        @Override
        public int observationSize() {
            return 2;
        }

        @Override
        public int actionSize() {
            return 1;
        }

        @Override
        public double[] reset(long seed) {
            rng = new Rng(seed);
            s = new double[] {rng.uniform(-1, 1), rng.uniform(-1, 1)};
            return s.clone();
        }

        @Override
        public Step step(double[] action) {
            boolean ok = Math.abs(action[0] - best(s)) <= 0.1;
            s = new double[] {rng.uniform(-1, 1), rng.uniform(-1, 1)};
            return new Step(s.clone(), ok ? 1 : 0, !ok, false);
        }

        @Override
        public Demonstration label(double[] proposal, long seed) {
            labels++;
            double f = best(s), d = proposal[0] - f;
            boolean ok = Math.abs(d) <= 0.1;
            return new Demonstration(new double[] {ok ? proposal[0] : f + Math.copySign(0.05, d)}, ok, 1, 1);
        }
    }

    private static DaggerConfig config(int rounds, boolean executeLabel) {
        LearnerConfig t = LearnTestSupport.config("ddpg.actorHidden", "[16, 16]", "pretrain.epochs", "40", "pretrain.batchSize", "32",
                "pretrain.validationFraction", "0.1");
        return new DaggerConfig(7, rounds, 20, 10, executeLabel, DaggerConfig.Weighting.UNIFORM, 0, DaggerConfig.Refit.FRESH, t.ddpg(), t.pretrain());
    }

    /** Plays the requests one after another on one environment. */
    private static Dagger.RoundPlayer on(Window env) {
        return (actor, requests) -> requests.stream().map(r -> Dagger.play(env, r, actor)).toList();
    }

    @Test
    void theLearnersOwnSuccessRisesRoundByRoundTowardTheTeachers() {
        Dagger dagger = new Dagger(config(3, true), 2, 1);
        Window env = new Window();
        Function<double[], double[]> actor = s -> new double[] {0};
        List<Dagger.Visit> all = new ArrayList<>();
        List<Double> success = new ArrayList<>();
        for (int r = 0; r < 3; r++) {
            Dagger.Round round = dagger.round(r, actor, null, on(env), all);
            round.episodes().forEach(e -> all.addAll(e.visits()));
            success.add(round.stats().proposalSuccessRate());
            assertEquals(all.size(), round.stats().examples(), "every label so far is fitted (all found, none filtered)");
            actor = round.policy()::act;
        }
        // a = 0 succeeds where |f(s)| <= 0.1: about a fifth of the states; after two rounds of labels the
        // actor has learned the window (a 0.2-wide target in a 1.6-wide range)
        assertTrue(success.get(0) < 0.3, "the constant start: " + success);
        assertTrue(success.get(2) > 0.8, "after two rounds of aggregated labels: " + success);
    }

    /** An environment whose episode ends before any decision of the learner's (TeachableEnv#reset null) gives an episode of none. */
    @Test
    void anEpisodeWithoutALearnersDecisionVisitsNone() {
        Window none = new Window() {
            @Override
            public double[] reset(long seed) {
                super.reset(seed);
                return null;
            }
        };
        Dagger.Episode e = Dagger.play(none, new Dagger.Request(0, 0, 3, 4, 10, true), s -> new double[] {0});
        assertEquals(0, e.visits().size());
        assertEquals(0, none.labels, "the teacher was not asked");
    }

    @Test
    void withoutExecutingTheLabelAnEpisodeEndsAtTheLearnersFirstFailure() {
        Dagger dagger = new Dagger(config(1, false), 2, 1);
        Dagger.Round round = dagger.round(0, s -> new double[] {0}, null, on(new Window()), List.of());
        for (Dagger.Episode e : round.episodes()) {
            List<Dagger.Visit> v = e.visits();
            for (int d = 0; d < v.size() - 1; d++) {
                assertTrue(v.get(d).label().proposalSucceeded(), "only the last decision of an episode may fail");
            }
            assertTrue(v.size() == 10 || !v.get(v.size() - 1).label().proposalSucceeded());
        }
    }

    @Test
    void aRoundIsAFunctionOfTheRootSeedAndTheRoundAlone() {
        Dagger dagger = new Dagger(config(2, true), 2, 1);
        Dagger.Round a = dagger.round(1, s -> new double[] {0.2}, null, on(new Window()), List.of());
        Dagger.Round b = dagger.round(1, s -> new double[] {0.2}, null, on(new Window()), List.of());
        assertEquals(a.stats(), b.stats());
        assertArrayEquals(a.policy().act(new double[] {0.3, -0.4}), b.policy().act(new double[] {0.3, -0.4}), 0);
        assertTrue(dagger.requests(0).get(0).envSeed() != dagger.requests(1).get(0).envSeed(), "rounds play other episodes");
    }

    @Test
    void labelsLessRobustThanTheFloorAreLeftOutAndRobustOnesWeighMore() {
        LearnerConfig t = LearnTestSupport.config("pretrain.epochs", "5");
        DaggerConfig c = new DaggerConfig(1, 1, 1, 1, true, DaggerConfig.Weighting.ROBUSTNESS, 0.5, DaggerConfig.Refit.FRESH, t.ddpg(), t.pretrain());
        List<Dagger.Visit> visits = new ArrayList<>();
        for (int i = 0; i < 10; i++) {
            visits.add(new Dagger.Visit(new double[] {i, 0}, new double[] {0}, new Demonstration(new double[] {0.1}, false, 3, i / 10.0)));
        }
        visits.add(new Dagger.Visit(new double[] {1, 1}, new double[] {0}, new Demonstration(null, false, 49, 0)));
        assertEquals(5, new Dagger(c, 2, 1).fit(visits, 3, "test", null).examples(), "robustness 0.5-0.9 kept; none without a label");
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> new Dagger(c, 2, 1).fit(visits.subList(0, 5), 3, "test", null));
        assertTrue(e.getMessage().contains("0 usable labels"), e.getMessage());
    }

    @Test
    void aContinuedFitKeepsTheActorItStartsFromWhereTheLabelsAgreeWithIt() {
        // labels that are the start actor's own actions: a continued fit stays near it, a fresh fit of
        // as few steps is far from it (it starts from near-zero outputs, finalLayerInit)
        LearnerConfig t = LearnTestSupport.config("ddpg.actorHidden", "[16, 16]", "pretrain.epochs", "3", "pretrain.validationFraction", "0",
                "pretrain.policyObservations", "10000");
        DaggerConfig fresh = new DaggerConfig(1, 1, 1, 1, true, DaggerConfig.Weighting.UNIFORM, 0, DaggerConfig.Refit.FRESH, t.ddpg(),
                t.pretrain());
        DaggerConfig continued = new DaggerConfig(1, 1, 1, 1, true, DaggerConfig.Weighting.UNIFORM, 0, DaggerConfig.Refit.CONTINUE,
                t.ddpg(), t.pretrain());
        Rng rng = new Rng(5);
        List<Dagger.Visit> toFit = new ArrayList<>(), agreeing = new ArrayList<>();
        for (int i = 0; i < 200; i++) {
            double[] s = {rng.uniform(-1, 1), rng.uniform(-1, 1)};
            toFit.add(new Dagger.Visit(s, new double[] {0}, new Demonstration(new double[] {Window.best(s)}, false, 1, 1)));
        }
        Policy start = new Dagger(fresh, 2, 1).fit(toFit, 1, "start", null).policy();
        for (Dagger.Visit v : toFit) {
            agreeing.add(new Dagger.Visit(v.observation(), start.act(v.observation()), new Demonstration(start.act(v.observation()), true, 1, 1)));
        }
        Policy kept = new Dagger(continued, 2, 1).fit(agreeing, 2, "continued", start).policy();
        Policy anew = new Dagger(fresh, 2, 1).fit(agreeing, 2, "fresh", start).policy();
        double keptGap = 0, freshGap = 0;
        for (Dagger.Visit v : agreeing) {
            keptGap = Math.max(keptGap, Math.abs(kept.act(v.observation())[0] - start.act(v.observation())[0]));
            freshGap = Math.max(freshGap, Math.abs(anew.act(v.observation())[0] - start.act(v.observation())[0]));
        }
        assertTrue(keptGap < 0.5 * freshGap, "continued " + keptGap + " against fresh " + freshGap);
        Json shipped = Json.load(Home.resolve("configs/train/flip-dagger.json"));
        ConfigException e = assertThrows(ConfigException.class, () -> DaggerConfig.parse(Json.of("test", Json.withOverrides("test",
                shipped.node(), Map.of("dagger.refit", "continue", "pretrain.policyObservations", "0")))));
        assertTrue(e.getMessage().contains("refit") && e.getMessage().contains("policyObservations"), e.getMessage());
    }

    @Test
    void theShippedConfigParsesAndABadFieldIsNamed() {
        DaggerConfig c = DaggerConfig.load(Home.resolve("configs/train/flip-dagger.json"));
        assertTrue(c.rounds() >= 1 && c.episodesPerRound() >= 1);
        Json shipped = Json.load(Home.resolve("configs/train/flip-dagger.json"));
        ConfigException e = assertThrows(ConfigException.class, () -> DaggerConfig.parse(Json.of("test",
                Json.withOverrides("test", shipped.node(), Map.of("dagger.weighting", "loud")))));
        assertTrue(e.getMessage().contains("weighting") && e.getMessage().contains("loud"), e.getMessage());
    }
}
