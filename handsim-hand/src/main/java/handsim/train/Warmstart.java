package handsim.train;

import handsim.sim.Simulator;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.learn.ActorPretraining;
import handsim.learn.Cmaes;
import handsim.learn.CmaesGenerations;
import handsim.learn.DdpgAgent;
import handsim.learn.Policy;
import handsim.learn.LearnerConfig;
import handsim.report.Outputs;
import handsim.report.Plot;
import handsim.rollout.Rollouts;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * The imitation warm start of paper sec. 4.4: for each of many seeded initial conditions (an
 * object caught, the first THROW about to be chosen), CMA-ES (Hansen 2006) searches the throw's
 * action for the best single throw; the throws that reach the task's success (a flip and a
 * catch) become (state, action) examples, and the actor is fitted to them by regression. A run
 * folder holds the config, {@code dataset.csv}, {@code searches.json}, the pretraining curves
 * and the pretrained actor as {@code pretrained-policy.json}.
 */
public final class Warmstart {

    public static final String DATASET = "dataset.csv";

    /**
     * The {@code warmstart} section of a warm-start config.
     *
     * @param initialConditions how many initial conditions (episode seeds firstSeed, firstSeed + 1, ...);
     *     at least 2, the fewest examples the actor's fit takes ({@link handsim.learn.ActorPretraining})
     * @param firstSeed the first episode seed
     * @param keepReward a searched throw becomes an example when its reward is at least this
     */
    public record Settings(int initialConditions, long firstSeed, double keepReward) {

        static Settings parse(Json j) {
            j.allow("comment");
            Settings s = new Settings(j.integer("initialConditions", 2, 100000), j.longValue("firstSeed"), j.number("keepReward"));
            j.requireNoUnknownFields();
            return s;
        }
    }

    /** A warm-start config: the {@code warmstart} section and a training config (run and learner sections). */
    public record Config(Settings warmstart, TrainConfig train) {

        /** A warm-start config: the {@code warmstart} section, and the rest as a training config. */
        public static Config parse(Json j) {
            Settings s = Settings.parse(j.get("warmstart"));
            ObjectNode rest = ((ObjectNode) j.node()).deepCopy();
            rest.remove("warmstart");
            return new Config(s, TrainConfig.parse(Json.of(j.source(), rest)));
        }

        public ObjectNode toJson() {
            ObjectNode root = Json.mapper().createObjectNode();
            root.set("warmstart", Json.mapper().valueToTree(warmstart));
            root.setAll(train.toJson());
            return root;
        }
    }

    /**
     * One search: the initial condition's state, the best action found, its reward, and
     * whether it was kept as an example.
     */
    public record Search(int index, long seed, double[] state, double[] action, double reward, int evaluations, boolean kept) {
    }

    private Warmstart() {
    }

    /**
     * Searches every initial condition, starting each search from the task's nominal throw: CMA-ES
     * a generation at a time, the throws of a generation of every search on the rollout workers
     * (shipped by {@code shipper} to a cluster, or null: this JVM's threads). A search's result is
     * {@link Cmaes#minimize}'s for its initial condition; results in seed order, each printed once
     * its search is over.
     */
    public static List<Search> search(Config c, ThrowEnvFactory envs, double[] nominalAction, Rollouts<Simulator> rollouts,
            WarmstartThrows.Shipper shipper, PrintStream out) {
        LearnerConfig.Cmaes cm = c.train().learner().cmaes();
        int n = c.warmstart().initialConditions();
        double[] lower = new double[nominalAction.length], upper = new double[nominalAction.length], sigma = new double[nominalAction.length];
        Arrays.fill(lower, -1);
        Arrays.fill(upper, 1);
        Arrays.fill(sigma, 2 * cm.initialSigma()); // the action range is 2 wide
        CmaesGenerations[] searches = new CmaesGenerations[n];
        double[][] states = new double[n][];
        for (int i = 0; i < n; i++) {
            // the objective is each throw's negated reward, a deterministic function of the action: evaluated by WarmstartThrows
            searches[i] = new CmaesGenerations(new Cmaes.Problem(null, nominalAction.clone(), sigma, lower, upper, cm.population(),
                    cm.maxEvaluations(), c.warmstart().firstSeed() + i));
        }
        WarmstartThrows throwsOf = new WarmstartThrows(envs);
        Search[] found = new Search[n];
        for (int generation = 0; ; generation++) {
            List<WarmstartThrows.Candidate> candidates = new ArrayList<>();
            int[] from = new int[n + 1];
            for (int i = 0; i < n; i++) {
                from[i] = candidates.size();
                for (double[] x : searches[i].next()) {
                    candidates.add(new WarmstartThrows.Candidate(c.warmstart().firstSeed() + i, x));
                }
                if (searches[i].done() && found[i] == null) {
                    found[i] = finished(i, c, states[i], searches[i].result(), out);
                }
            }
            from[n] = candidates.size();
            if (candidates.isEmpty()) {
                break;
            }
            int active = (int) java.util.stream.IntStream.range(0, n).filter(i -> from[i + 1] > from[i]).count();
            out.printf(Locale.ROOT, "generation %d: %d throws of %d searches%n", generation, candidates.size(), active);
            List<WarmstartThrows.Outcome> outcomes = rollouts.run(candidates.size(), throwsOf.task(generation, candidates, shipper));
            for (int i = 0; i < n; i++) {
                double[] values = new double[from[i + 1] - from[i]];
                for (int j = 0; j < values.length; j++) {
                    WarmstartThrows.Outcome o = outcomes.get(from[i] + j);
                    values[j] = -o.reward();
                    states[i] = o.state();
                }
                if (values.length > 0) {
                    searches[i].tell(values);
                }
            }
        }
        return List.of(found);
    }

    private static Search finished(int i, Config c, double[] state, Cmaes.Result r, PrintStream out) {
        long seed = c.warmstart().firstSeed() + i;
        double reward = -r.value();
        Search s = new Search(i, seed, state, r.point(), reward, r.evaluations(), reward >= c.warmstart().keepReward());
        out.printf(Locale.ROOT, "initial condition %d (seed %d): best reward %.3f after %d evaluations%s%n", i, s.seed(),
                s.reward(), s.evaluations(), s.kept() ? ", kept" : "");
        return s;
    }

    /** Writes the kept searches as the dataset: seed, reward, the state entries and the action entries. */
    public static void writeDataset(Path file, List<Search> searches) throws IOException {
        List<Search> kept = searches.stream().filter(Search::kept).toList();
        if (kept.isEmpty()) {
            throw new IllegalStateException("no search reached the keep reward: there is no dataset");
        }
        int n = kept.get(0).state().length, k = kept.get(0).action().length;
        StringBuilder sb = new StringBuilder("seed,reward");
        for (int i = 0; i < n; i++) {
            sb.append(",s").append(i);
        }
        for (int i = 0; i < k; i++) {
            sb.append(",a").append(i);
        }
        sb.append('\n');
        for (Search s : kept) {
            sb.append(s.seed()).append(',').append(s.reward());
            for (double v : s.state()) {
                sb.append(',').append(v);
            }
            for (double v : s.action()) {
                sb.append(',').append(v);
            }
            sb.append('\n');
        }
        Outputs.writeString(file, sb.toString());
    }

    /** A dataset as (states, actions); {@code path} is the CSV or a warm-start folder holding it. */
    public static double[][][] readDataset(Path path, int stateSize, int actionSize) throws IOException {
        Path file = Files.isDirectory(path) ? path.resolve(DATASET) : path;
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException("no warm-start dataset at " + file);
        }
        List<String> lines = Files.readAllLines(file);
        int expected = 2 + stateSize + actionSize;
        List<double[]> states = new ArrayList<>(), actions = new ArrayList<>();
        for (int row = 1; row < lines.size(); row++) {
            String[] cells = lines.get(row).split(",");
            if (cells.length != expected) {
                throw new IllegalArgumentException(file + " line " + (row + 1) + ": " + cells.length + " columns, expected " + expected
                        + " (seed, reward, " + stateSize + " state and " + actionSize + " action entries): a dataset for another task?");
            }
            double[] v = Arrays.stream(cells).mapToDouble(Double::parseDouble).toArray();
            states.add(Arrays.copyOfRange(v, 2, 2 + stateSize));
            actions.add(Arrays.copyOfRange(v, 2 + stateSize, expected));
        }
        if (states.size() < 2) {
            throw new IllegalArgumentException(file + ": at least 2 examples are needed, got " + states.size());
        }
        return new double[][][] {states.toArray(double[][]::new), actions.toArray(double[][]::new)};
    }

    /**
     * A fresh agent (the run's seed) whose actor is fitted to the dataset with the run's
     * pretraining settings: the start of a warm-started training run, and what the warm start
     * saves. Deterministic.
     */
    public static DdpgAgent pretrainedAgent(TrainConfig c, int stateSize, int actionSize, double[][][] data,
            ActorPretraining.Result[] result) {
        LearnerConfig l = c.learner();
        DdpgAgent agent = seededAgent(l, stateSize, actionSize);
        ActorPretraining.Result r = ActorPretraining.fit(agent, data[0], data[1], l.pretrain(), l.seed());
        if (result != null) {
            result[0] = r;
        }
        return agent;
    }

    /**
     * A fresh agent as {@link handsim.learn.Trainer#create} makes it (the root seed's first draw),
     * so a warm-started or fine-tuning run differs from a cold one by its actor's start alone.
     */
    static DdpgAgent seededAgent(LearnerConfig l, int stateSize, int actionSize) {
        return DdpgAgent.create(l.ddpg(), stateSize, actionSize, new handsim.learn.Rng(l.seed()).nextLong());
    }

    /** The pretraining curves (training and held-out mean squared error per epoch). */
    public static void plotPretraining(Path png, ActorPretraining.Result r, String title) throws IOException {
        double[] epochs = new double[r.trainLoss().length];
        for (int i = 0; i < epochs.length; i++) {
            epochs[i] = i + 1;
        }
        new Plot(title, "epoch", "mean squared error per action entry")
                .add("training (" + r.trainExamples() + " examples)", epochs, r.trainLoss(), Plot.BLUE, Plot.Style.LINE)
                .add("held out (" + r.validationExamples() + ")", epochs, r.validationLoss(), Plot.ORANGE, Plot.Style.LINE)
                .writePng(png);
    }

    /** The pretrained actor as a throw policy file. */
    public static ThrowPolicyFile policyFile(DdpgAgent agent, TrainConfig c, ThrowEnvFactory envs, ObjectNode provenance) {
        Policy actor = agent.policy("pretrained on the warm-start dataset (" + c.run().task() + ", " + c.run().object() + ")",
                "ThrowSpace, see throwSpace");
        return new ThrowPolicyFile(c.run().task(), c.run().object(), envs.state().encoding(), envs.space(), actor, provenance);
    }
}
