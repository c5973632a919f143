package handsim.train;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.control.Observation;
import handsim.control.ThrowParameters;
import handsim.control.ThrowPolicy;
import handsim.learn.Dagger;
import handsim.learn.DaggerEpisodes;
import handsim.learn.DemonstrationSet;
import handsim.learn.Policy;
import handsim.report.Outputs;
import handsim.rollout.PortableTask;
import handsim.rollout.RecordedTask;
import handsim.rollout.RolloutTask;
import handsim.rollout.Rollouts;
import handsim.rollout.ShippableTask;
import handsim.sim.Simulator;
import handsim.planning.ThrowTeacher;
import handsim.task.ThrowTask;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import java.util.function.Predicate;

/**
 * One DAgger run of a throw task in its folder ({@code runs/dagger__<name>__<seed>__<time>/}):
 * {@code config.json} and {@code run.json} (command, commit), {@code demonstrations.csv} (every
 * decision visited with the learner's proposal and the teacher's label, written as episodes
 * finish), {@code rounds.csv} (one row per round: the learner's throw success on the states it
 * visited, the teacher's cost, the fit), {@code policies/round-NN.json} (the actor fitted after
 * round NN, a shipped throw policy) and {@code policy.json} (the last). Round 0's learner is the
 * task's nominal throw, or the policy the run started from ({@code init-policy.json}); with the
 * config's {@code learnerThrows} it makes only the throws from one rest, lead-in policies the
 * others ({@code lead-in.json}, {@code lead-in-opening.json}: copies made when the run starts).
 * A run killed at any moment resumes: finished rounds are read back, and the finished episodes
 * of the round in progress are not played again (but for those that gave no decision to label,
 * which are played again to the same end: their seeds decide them).
 *
 * <p>Each rollout worker has a twin simulator of its own for its teacher ({@code twins} makes it
 * from the worker's simulator); they are closed when the run ends.
 */
public final class DaggerRun {

    public static final String CONFIG = "config.json";
    public static final String RUN_JSON = "run.json";
    public static final String DEMONSTRATIONS = "demonstrations.csv";
    public static final String ROUNDS = "rounds.csv";
    public static final String POLICY = "policy.json";
    /** The policy of round 0's learner, when the run did not start from the nominal throw. */
    public static final String INIT_POLICY = "init-policy.json";
    /** The lead-in policy files of a config's {@code learnerThrows}, as they were when the run started. */
    public static final String LEAD_IN = "lead-in.json";
    public static final String LEAD_IN_OPENING = "lead-in-opening.json";

    private static final String ROUNDS_HEADER = "round,episodes,decisions,proposal_successes,proposal_success_rate,labelled,tries,"
            + "tries_per_decision,examples,train_loss,validation_loss,round_seconds";

    private final Path dir;
    private final DaggerRunConfig config;
    private final ThrowEnvFactory envs;
    private final Rollouts<Simulator> rollouts;
    private final Function<Simulator, Simulator> twins;
    private final ObjectNode startedBy;
    private Shipper shipper;

    /** A round's episodes in the form that travels to a cluster (the app builds it from the run's configuration documents). */
    @FunctionalInterface
    public interface Shipper {

        /**
         * Round {@code round}'s episodes {@code requests} played by {@code actor} (a network's
         * policy, or null for the task's nominal throw), the learner throwing from {@code
         * learnerThrows} (null: every decision) with the lead-in policies it names.
         */
        PortableTask<Simulator> ship(int round, Policy actor, List<Dagger.Request> requests, DaggerRunConfig.LearnerThrows learnerThrows);
    }

    private DaggerRun(Path dir, DaggerRunConfig config, ThrowEnvFactory envs, Rollouts<Simulator> rollouts, Function<Simulator, Simulator> twins) {
        this.dir = dir;
        this.config = config;
        this.envs = envs;
        this.rollouts = rollouts;
        this.twins = twins;
        Json started = Json.load(dir.resolve(RUN_JSON));
        this.startedBy = Json.mapper().createObjectNode();
        for (String key : List.of("command", "commit")) {
            if (started.has(key)) {
                startedBy.put(key, started.string(key));
            }
        }
    }

    /**
     * A new run in {@code dir} (created; it must not hold a run already) of {@code configFile}'s
     * settings (copied into the run as they are), with {@code provenance} in {@code run.json};
     * round 0's learner is {@code initPolicy} (a throw policy file of the run's task, object and
     * state), or the task's nominal throw when null.
     */
    public static DaggerRun start(Path dir, Json configFile, ThrowEnvFactory envs, Rollouts<Simulator> rollouts, Function<Simulator, Simulator> twins,
            ObjectNode provenance, Path initPolicy) throws IOException {
        if (Files.exists(dir.resolve(CONFIG))) {
            throw new IllegalArgumentException(dir + " already holds a run (resume it with --resume " + dir + ")");
        }
        DaggerRunConfig config = DaggerRunConfig.parse(configFile);
        if (initPolicy != null) {
            ThrowPolicyFile.initActor(initPolicy, envs); // refused before the folder is written
        }
        gate(config.learnerThrows(), envs.tasks().get(), envs); // lead-in policies for another task or object too
        Files.createDirectories(dir);
        Outputs.writeJson(dir.resolve(CONFIG), configFile.node());
        Outputs.writeJson(dir.resolve(RUN_JSON), provenance);
        if (initPolicy != null) {
            copy(initPolicy, dir.resolve(INIT_POLICY));
        }
        if (config.learnerThrows() != null) {
            copy(config.learnerThrows().leadIn(), dir.resolve(LEAD_IN));
            if (config.learnerThrows().leadInOpening() != null) {
                copy(config.learnerThrows().leadInOpening(), dir.resolve(LEAD_IN_OPENING));
            }
        }
        return new DaggerRun(dir, config, envs, rollouts, twins);
    }

    /** A copy of {@code from} at {@code to}, written atomically (a killed start leaves no half file for a resume to read). */
    private static void copy(Path from, Path to) throws IOException {
        Outputs.write(to, out -> Files.copy(from, out));
    }

    /** Continues the run in {@code dir} with the config saved there (and the lead-in policies copied there). */
    public static DaggerRun resume(Path dir, ThrowEnvFactory envs, Rollouts<Simulator> rollouts, Function<Simulator, Simulator> twins) {
        Path file = dir.resolve(CONFIG);
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException(dir + " is not a DAgger run folder (no " + CONFIG + ")");
        }
        return new DaggerRun(dir, DaggerRunConfig.load(file), envs, rollouts, twins);
    }

    /** The config saved in a run folder. */
    public static DaggerRunConfig savedConfig(Path dir) {
        return DaggerRunConfig.load(dir.resolve(CONFIG));
    }

    public Path dir() {
        return dir;
    }

    /**
     * This run with its rounds' episodes shipped by {@code shipper} to the cluster its rollouts
     * run on: the driver still reads back the episodes a killed run finished and alone writes
     * the run's files.
     */
    public DaggerRun onCluster(Shipper shipper) {
        this.shipper = shipper;
        return this;
    }

    /** Plays the rounds not yet finished, printing a line per round (and progress within it) to {@code out}. */
    public void run(PrintStream out) throws IOException {
        int n = envs.observationSize(), k = ThrowParameters.SIZE;
        Dagger dagger = new Dagger(config.learner(), n, k);
        DemonstrationSet set = new DemonstrationSet(dir.resolve(DEMONSTRATIONS), n, k, TeachableThrowEnv.OUTCOMES);
        Map<Integer, Map<Integer, List<Dagger.Visit>>> journal = set.read();
        int finished = finishedRounds();
        List<Dagger.Visit> earlier = new ArrayList<>();
        for (int r = 0; r < finished; r++) {
            journal.getOrDefault(r, Map.of()).values().forEach(earlier::addAll);
        }
        Policy network = finished == 0 ? initialPolicy() : roundPolicy(finished - 1);
        Function<double[], double[]> actor = network != null ? network::act : nominalActor();
        Map<Simulator, TeachableThrowEnv> workers = Collections.synchronizedMap(new IdentityHashMap<>());
        List<Simulator> twinSims = Collections.synchronizedList(new ArrayList<>());
        out.printf(Locale.ROOT, "DAgger %s (%s task, %s) in %s: rounds %d..%d of %d, %d episodes each on %d workers%n",
                config.run().name(), config.run().task(), config.run().object(), dir, finished, config.learner().rounds() - 1,
                config.learner().rounds(), config.learner().episodesPerRound(), rollouts.workers());
        try {
            for (int r = finished; r < config.learner().rounds(); r++) {
                long t0 = System.nanoTime();
                Map<Integer, List<Dagger.Visit>> kept = journal.getOrDefault(r, Map.of());
                Progress progress = new Progress(out, r, config.learner().episodesPerRound(), config.run().progressSeconds());
                Policy learner = network;
                int roundNumber = r;
                Dagger.Round round = dagger.round(r, actor, network, (a, requests) -> rollouts.run(requests.size(),
                        roundTask(roundNumber, a, learner, requests, kept, set, workers, twinSims), progress::onEpisode), earlier);
                round.episodes().forEach(e -> earlier.addAll(e.visits()));
                set.sortEpisodes(); // the round's rows in episode order, however its episodes finished
                double seconds = (System.nanoTime() - t0) * 1e-9;
                savePolicy(round.policy(), r);
                appendRound(round.stats(), seconds);
                Dagger.RoundStats s = round.stats();
                out.printf(Locale.ROOT, "round %d: the learner's own throw succeeded at %d of %d decisions (%.1f %%); the teacher "
                        + "labelled %d with %d tries (%.1f per decision); the actor fitted to %d labels (loss %.4f, held out %.4f); "
                        + "%.0f s%n", r, s.proposalSuccesses(), s.decisions(), 100 * s.proposalSuccessRate(), s.labelled(), s.tries(),
                        (double) s.tries() / Math.max(1, s.decisions()), s.examples(), s.trainLoss(), s.validationLoss(), seconds);
                network = round.policy();
                actor = network::act;
            }
        } finally {
            twinSims.forEach(Simulator::close);
        }
        out.println("wrote " + dir.resolve(POLICY) + ", " + ROUNDS + ", " + DEMONSTRATIONS);
    }

    /**
     * Round {@code round}'s episodes as a rollout task: the episodes a killed run finished
     * ({@code kept}) read back, the others played by the workers' environments (made once per
     * worker) and appended to the demonstration set as they finish, by the driver alone; shipped
     * to a cluster as {@link #shipper} makes them when there is one.
     */
    private RolloutTask<Simulator, Dagger.Episode> roundTask(int round, Function<double[], double[]> actor, Policy network,
            List<Dagger.Request> requests, Map<Integer, List<Dagger.Visit>> kept, DemonstrationSet set,
            Map<Simulator, TeachableThrowEnv> workers, List<Simulator> twinSims) {
        RolloutTask<Simulator, Dagger.Episode> local = sim -> {
            TeachableThrowEnv env = workers.computeIfAbsent(sim, s -> {
                Simulator twin = twins.apply(s);
                twinSims.add(twin);
                return teachableEnv(config, learnerThrows(), envs, s, twin);
            });
            return i -> Dagger.play(env, requests.get(i), actor);
        };
        RecordedTask<Simulator, Dagger.Episode> recorded = new RecordedTask<>(local, DaggerEpisodes::toJson, DaggerEpisodes::fromJson,
                new RecordedTask.Journal() {
                    @Override
                    public Optional<JsonNode> finished(int index) {
                        Dagger.Request req = requests.get(index);
                        return kept.containsKey(req.episode()) ? Optional.of(DaggerEpisodes.toJson(new Dagger.Episode(req, kept.get(req.episode()))))
                                : Optional.empty();
                    }

                    @Override
                    public void append(int index, JsonNode episode) {
                        try {
                            set.append(DaggerEpisodes.fromJson(episode));
                        } catch (IOException ex) {
                            throw new java.io.UncheckedIOException(ex);
                        }
                    }
                });
        return shipper == null ? recorded
                : new ShippableTask<>(recorded, shipper.ship(round, network, requests, learnerThrows()), DaggerEpisodes::fromJson);
    }

    /**
     * The environment a DAgger worker plays on {@code sim}: the task's throw environment with the
     * twin-world teacher on {@code twin}, and the learner's decisions gated by {@code throwsOf}
     * (lead-in policies throwing the others; null: every decision is the learner's).
     */
    public static TeachableThrowEnv teachableEnv(DaggerRunConfig config, DaggerRunConfig.LearnerThrows throwsOf, ThrowEnvFactory envs,
            Simulator sim, Simulator twin) {
        ThrowEnv throwEnv = envs.create(sim);
        return new TeachableThrowEnv(throwEnv, new ThrowTeacher(config.teacher(), envs.tasks().get(), envs.space(), twin),
                gate(throwsOf, throwEnv.task(), envs));
    }

    /**
     * The decisions the learner makes in an environment playing {@code task}: all (null) without
     * {@code throwsOf}, else those from its rest, the lead-in policies throwing the others.
     */
    private static TeachableThrowEnv.Gate gate(DaggerRunConfig.LearnerThrows throwsOf, ThrowTask task, ThrowEnvFactory envs) {
        if (throwsOf == null) {
            return null;
        }
        Predicate<Observation> learnerThrows;
        try {
            learnerThrows = throwsOf.rest().decisionsOf(envs.object());
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("learnerThrows.rest: " + e.getMessage(), e);
        }
        requireFile("leadIn", throwsOf.leadIn());
        requireFile("leadInOpening", throwsOf.leadInOpening());
        ThrowPolicy leadIn;
        try {
            leadIn = ThrowPolicyFile.throwPolicy(throwsOf.leadIn(), throwsOf.leadInOpening(), null, task, envs.object(),
                    envs.state().hand());
        } catch (IllegalArgumentException e) { // ConfigException is one: a file that cannot be read
            throw new IllegalArgumentException("learnerThrows.leadIn " + throwsOf.leadIn() + (throwsOf.leadInOpening() == null ? ""
                    : " or leadInOpening " + throwsOf.leadInOpening()) + ": " + e.getMessage(), e);
        }
        return new TeachableThrowEnv.Gate(learnerThrows, leadIn, throwsOf.maxLoops());
    }

    /** Refuses a lead-in file (when one is named) that does not exist, naming its field. */
    private static void requireFile(String field, Path file) {
        if (file != null && !Files.isRegularFile(file)) {
            throw new IllegalArgumentException("learnerThrows." + field + ": no file " + file);
        }
    }

    /**
     * The config's {@code learnerThrows} with the lead-in policies the run copied when it started
     * (so a resumed run throws as it began, whatever became of the files the config names); a
     * folder without the copies reads the files the config names.
     */
    private DaggerRunConfig.LearnerThrows learnerThrows() {
        DaggerRunConfig.LearnerThrows t = config.learnerThrows();
        if (t == null) {
            return null;
        }
        return new DaggerRunConfig.LearnerThrows(t.rest(), copied(LEAD_IN, t.leadIn()),
                t.leadInOpening() == null ? null : copied(LEAD_IN_OPENING, t.leadInOpening()), t.maxLoops());
    }

    private Path copied(String name, Path named) {
        Path copy = dir.resolve(name);
        return Files.isRegularFile(copy) ? copy : named;
    }

    /** Round 0's learner when the run started from a policy, else null (the nominal throw). */
    private Policy initialPolicy() {
        Path init = dir.resolve(INIT_POLICY);
        return Files.isRegularFile(init) ? ThrowPolicyFile.initActor(init, envs).policy() : null;
    }

    /** The task's nominal throw from every state. */
    private Function<double[], double[]> nominalActor() {
        return nominalActor(envs);
    }

    /** The nominal throw of {@code envs}' task from every state: round 0's learner when the run starts from none. */
    public static Function<double[], double[]> nominalActor(ThrowEnvFactory envs) {
        double[] nominal = envs.space().toAction(envs.tasks().get().nominalThrow());
        return obs -> nominal.clone();
    }

    private Path roundPolicyFile(int round) {
        return dir.resolve("policies").resolve(String.format(Locale.ROOT, "round-%02d.json", round));
    }

    private Policy roundPolicy(int round) {
        return ThrowPolicyFile.load(roundPolicyFile(round)).policy();
    }

    private void savePolicy(Policy actor, int round) throws IOException {
        ObjectNode provenance = Json.mapper().createObjectNode();
        provenance.put("run", dir.getFileName().toString());
        provenance.put("method", "DAgger with the twin-world teacher (handsim.planning.ThrowTeacher)");
        provenance.put("round", round);
        provenance.setAll(startedBy);
        provenance.set("config", Json.load(dir.resolve(CONFIG)).node());
        Policy noted = new Policy(actor.mean(), actor.std(), actor.clip(), actor.layers(), config.run().task() + " task, "
                + config.run().object() + ", DAgger run " + dir.getFileName() + ", round " + round, "ThrowSpace, see throwSpace");
        ThrowPolicyFile file = new ThrowPolicyFile(config.run().task(), config.run().object(), envs.state().encoding(), envs.space(),
                noted, provenance);
        file.save(roundPolicyFile(round));
        file.save(dir.resolve(POLICY));
    }

    /** Rounds whose row is in rounds.csv (their policy was saved before the row). */
    private int finishedRounds() throws IOException {
        Path file = dir.resolve(ROUNDS);
        if (!Files.exists(file)) {
            return 0;
        }
        return (int) Files.readAllLines(file, StandardCharsets.UTF_8).stream().skip(1).filter(l -> !l.isBlank()).count();
    }

    private void appendRound(Dagger.RoundStats s, double seconds) throws IOException {
        Path file = dir.resolve(ROUNDS);
        String row = String.format(Locale.ROOT, "%d,%d,%d,%d,%.4f,%d,%d,%.3f,%d,%.6f,%.6f,%.1f%n", s.round(), s.episodes(), s.decisions(),
                s.proposalSuccesses(), s.proposalSuccessRate(), s.labelled(), s.tries(), (double) s.tries() / Math.max(1, s.decisions()),
                s.examples(), s.trainLoss(), s.validationLoss(), seconds);
        Outputs.append(file, ((Files.exists(file) ? "" : ROUNDS_HEADER + "\n") + row).getBytes(StandardCharsets.UTF_8));
    }

    /** A progress line at most every few seconds within a round: episodes done, and the learner's successes so far. */
    private static final class Progress {
        private final PrintStream out;
        private final int round;
        private final int episodes;
        private final double everySeconds;
        private final long t0 = System.nanoTime();
        private long lastPrint = System.nanoTime();
        private int done;
        private int decisions;
        private int successes;

        Progress(PrintStream out, int round, int episodes, double everySeconds) {
            this.out = out;
            this.round = round;
            this.episodes = episodes;
            this.everySeconds = everySeconds;
        }

        synchronized void onEpisode(int index, Dagger.Episode e) {
            done++;
            for (Dagger.Visit v : e.visits()) {
                decisions++;
                successes += v.label().proposalSucceeded() ? 1 : 0;
            }
            long now = System.nanoTime();
            if ((now - lastPrint) * 1e-9 >= everySeconds || done == episodes) {
                out.printf(Locale.ROOT, "round %d: %d/%d episodes, the learner's throw succeeded at %d of %d decisions, %.0f s%n",
                        round, done, episodes, successes, decisions, (now - t0) * 1e-9);
                lastPrint = now;
            }
        }
    }
}
