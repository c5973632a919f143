package handsim.train;

import handsim.sim.Simulator;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.learn.Checkpoints;
import handsim.learn.DdpgAgent;
import handsim.learn.EpisodeStats;
import handsim.learn.LearningCurves;
import handsim.learn.MetricsCsv;
import handsim.learn.Policy;
import handsim.learn.EpisodePlayer;
import handsim.learn.Trainer;
import handsim.learn.LearnerConfig;
import handsim.learn.TrainingListener;
import handsim.config.ReadLog;
import handsim.report.Outputs;
import handsim.report.Stop;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;

/**
 * One training run in its folder ({@code runs/<task>__<name>__<seed>__<time>/}): the merged
 * {@code config.json} and {@code run.json} (seed, commit, command), {@code metrics.csv} (one
 * row per episode, flushed as it comes), {@code checkpoint.zip} (the whole learner, written
 * atomically every {@code checkpointEveryEpisodes} episodes and at the end), the learning
 * curves {@code learning.png} and {@code losses.png} (paper Fig. 6, 9) and {@code policy.json},
 * the actor as a shipped throw policy, refreshed with every checkpoint and also kept as
 * {@code policies/episode-N.json} (to find when the run reached a level). A run killed at any
 * moment resumes from its last checkpoint; the episodes after it are played again, the same.
 *
 * <p>Episodes are played in rounds of {@code parallelEpisodes} on the rollout workers (each
 * with its own simulator), with the policy as it was when the round began; then the learner
 * does the round's updates.
 */
public final class TrainRun {

    public static final String CONFIG = "config.json";
    /** Provenance: command, seed, commit, and the budget extensions. */
    public static final String RUN_JSON = "run.json";
    public static final String CHECKPOINT = "checkpoint.zip";
    /** The checkpoint before the last one, kept for a resume that finds the last one damaged. */
    public static final String PREVIOUS_CHECKPOINT = "checkpoint-previous.zip";
    /** The folder of the policy snapshots {@code episode-N.json}. */
    public static final String SNAPSHOTS = "policies";
    public static final String METRICS = "metrics.csv";
    public static final String POLICY = "policy.json";
    /** A warm-started run's copy of its imitation dataset. */
    public static final String INIT_DATASET = "init-dataset.csv";
    /** A fine-tuning run's copy of the policy its actor started as. */
    public static final String INIT_POLICY = "init-policy.json";
    /** The field of run.json that names the run for its checkpoints (the folder's name when it started). */
    static final String RUN_ID = "runId";

    private final Path dir;
    private final TrainConfig config;
    private final ThrowEnvFactory envs;
    private final handsim.rollout.Rollouts<Simulator> rollouts;
    private final Trainer trainer;
    /** The command and commit that started the run (from run.json), written into every policy file. */
    private final ObjectNode startedBy;
    /** The episodes of the learner's state in checkpoint.zip: a new run starts from none, a resumed one from its checkpoint's. */
    private long checkpointed;

    private TrainRun(Path dir, TrainConfig config, ThrowEnvFactory envs, handsim.rollout.Rollouts<Simulator> rollouts, Trainer trainer) {
        Json started = Json.load(dir.resolve(RUN_JSON));
        this.startedBy = Json.mapper().createObjectNode();
        for (String key : List.of("command", "commit")) {
            if (started.has(key)) {
                startedBy.put(key, started.string(key));
            }
        }
        this.dir = dir;
        this.config = config;
        this.envs = envs;
        this.rollouts = rollouts;
        this.trainer = trainer;
        this.checkpointed = trainer.episodes();
    }

    /**
     * A new run in {@code dir} (created; it must not hold a run already), with {@code provenance}
     * (seed, commit, command line) written to {@code run.json}.
     */
    public static TrainRun start(Path dir, TrainConfig config, ThrowEnvFactory envs, handsim.rollout.Rollouts<Simulator> rollouts,
            ObjectNode provenance) throws IOException {
        return start(dir, config, envs, rollouts, provenance, null);
    }

    /**
     * A new run whose actor starts fitted to an imitation dataset (the warm start of sec. 4.4;
     * {@code initActor} is a {@link Warmstart} dataset or its folder), or as a trained throw
     * policy ({@code initActor} a {@code .json} policy file, fine-tuned on this run's task and
     * physics), or from scratch when null. The dataset or policy is copied into the run.
     */
    public static TrainRun start(Path dir, TrainConfig config, ThrowEnvFactory envs, handsim.rollout.Rollouts<Simulator> rollouts,
            ObjectNode provenance, Path initActor) throws IOException {
        if (Files.exists(dir.resolve(CONFIG))) {
            throw new IllegalArgumentException(dir + " already holds a run (resume it with --resume " + dir + ")");
        }
        boolean isPolicy = initActor != null && initActor.getFileName().toString().endsWith(".json");
        // read before anything is written
        double[][][] data = initActor == null || isPolicy ? null : readDataset(initActor, envs);
        Policy policy = isPolicy ? initPolicy(initActor, config, envs) : null;
        Files.createDirectories(dir);
        Outputs.writeJson(dir.resolve(CONFIG), config.toJson());
        ObjectNode runJson = provenance.deepCopy();
        runJson.put(RUN_ID, dir.getFileName().toString()); // its checkpoints name it: a resume takes no other run's
        Outputs.writeJson(dir.resolve(RUN_JSON), runJson);
        if (isPolicy) {
            Outputs.copy(initActor, dir.resolve(INIT_POLICY));
        } else if (initActor != null) {
            Outputs.copy(Files.isDirectory(initActor) ? initActor.resolve(Warmstart.DATASET) : initActor, dir.resolve(INIT_DATASET));
        }
        return new TrainRun(dir, config, envs, rollouts, freshTrainer(config, envs, data, policy));
    }

    /** The trainer of a run's start: from scratch, with the actor fitted to the imitation data, or as a policy. */
    private static Trainer freshTrainer(TrainConfig config, ThrowEnvFactory envs, double[][][] data, Policy policy) {
        int n = envs.observationSize(), k = handsim.control.ThrowParameters.SIZE;
        if (policy != null) {
            LearnerConfig l = config.learner();
            DdpgAgent agent = Warmstart.seededAgent(l, n, k);
            agent.startActorFrom(policy, l.pretrain().policyObservations());
            return Trainer.withAgent(l, agent);
        }
        return data == null ? Trainer.create(config.learner(), n, k)
                : Trainer.withAgent(config.learner(), Warmstart.pretrainedAgent(config, n, k, data, null));
    }

    /**
     * The actor of a throw policy file, checked against the run: the same task, object, state
     * encoding and throw space, and a set {@code pretrain.policyObservations}.
     */
    private static Policy initPolicy(Path file, TrainConfig config, ThrowEnvFactory envs) {
        ThrowPolicyFile f = ThrowPolicyFile.initActor(file, envs);
        if (config.learner().pretrain().policyObservations() == 0) {
            throw new IllegalArgumentException("--init-actor " + file + " is a policy: set pretrain.policyObservations, "
                    + "how many observations its normaliser's statistics count as");
        }
        return f.policy();
    }

    /** A warm-start dataset as (states, actions) sized for {@code envs}' observations and the throw parameters. */
    private static double[][][] readDataset(Path file, ThrowEnvFactory envs) throws IOException {
        return Warmstart.readDataset(file, envs.observationSize(), handsim.control.ThrowParameters.SIZE);
    }

    /** The configuration saved in a run folder. */
    public static TrainConfig savedConfig(Path dir) {
        Path file = dir.resolve(CONFIG);
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException(dir + " is not a run folder (no " + CONFIG + ")");
        }
        return TrainConfig.load(file);
    }

    /**
     * Raises the episode budget of the run in {@code dir} to {@code episodes} (it resumes with
     * {@link #resume}). The learner's schedules count decisions, not the budget, so a finished
     * run extended this way continues exactly as a run configured with the larger budget from its
     * start, as long as the old budget was a whole number of rounds ({@code parallelEpisodes}).
     * The saved config gets the new budget and {@code run.json} a record of the extension:
     * {@code provenance} (command, commit, time) with the old and new budgets. A budget equal to
     * the run's own changes nothing (so a killed extension is resumed by the same command).
     *
     * @return the saved config with the new budget
     */
    public static TrainConfig extend(Path dir, long episodes, ObjectNode provenance) throws IOException {
        TrainConfig old = savedConfig(dir);
        long before = old.learner().training().episodes();
        if (episodes < before) {
            throw new IllegalArgumentException("--episodes " + episodes + " is below the run's budget of " + before
                    + " episodes: a run can only be extended");
        }
        if (episodes == before) {
            return old;
        }
        TrainConfig extended = TrainConfig.parse(Json.of(dir.resolve(CONFIG).toString(), Json.withOverrides(CONFIG,
                old.toJson(), Map.of("training.episodes", Long.toString(episodes)))));
        ObjectNode record = provenance.deepCopy();
        record.put("from", before);
        record.put("to", episodes);
        ObjectNode runJson = (ObjectNode) Json.load(dir.resolve(RUN_JSON)).node();
        runJson.withArray("extended").add(record);
        Outputs.writeJson(dir.resolve(CONFIG), extended.toJson());
        Outputs.writeJson(dir.resolve(RUN_JSON), runJson);
        return extended;
    }

    /** {@link #resume(Path, ThrowEnvFactory, handsim.rollout.Rollouts, boolean, Consumer)} without fallback, notes to standard error. */
    public static TrainRun resume(Path dir, ThrowEnvFactory envs, handsim.rollout.Rollouts<Simulator> rollouts) throws IOException {
        return resume(dir, envs, rollouts, false, System.err::println);
    }

    /**
     * Continues the run in {@code dir} from its checkpoint. A run stopped before its first
     * checkpoint (it has written no checkpoint and no policy yet) starts again from episode 1:
     * the episodes it played are played again, the same. When a run that had a checkpoint lacks a
     * usable one (missing, or damaged), the resume is refused with what is missing, and nothing in
     * the folder changes, unless {@code fromSnapshot}: then the run goes on from the newest intact
     * of {@link #PREVIOUS_CHECKPOINT} (the checkpoint before the last: the run stays the one it
     * was) and the policy snapshots {@code policies/episode-N.json} (the actor as it was at
     * episode N with a new critic and an empty replay buffer, {@link Trainer#continueFrom}: the
     * rest of the run differs from the lost one), recorded in {@code run.json} under
     * {@code "fallbacks"}. Leftovers of a killed write are deleted; {@code notes} hears what was
     * done.
     */
    public static TrainRun resume(Path dir, ThrowEnvFactory envs, handsim.rollout.Rollouts<Simulator> rollouts, boolean fromSnapshot,
            Consumer<String> notes) throws IOException {
        TrainConfig config = savedConfig(dir);
        String problem;
        ObjectNode identity = identity(dir, config);
        try {
            Trainer trainer = ResumePoint.checkpoint(dir.resolve(CHECKPOINT), config, identity, notes);
            sweepTemporaryFiles(dir);
            return new TrainRun(dir, config, envs, rollouts, trainer);
        } catch (NoSuchFileException e) {
            if (!ResumePoint.everCheckpointed(dir)) {
                notes.accept(dir + " stopped before its first checkpoint: training from episode 1");
                sweepTemporaryFiles(dir);
                return new TrainRun(dir, config, envs, rollouts, initialTrainer(dir, config, envs));
            }
            problem = CHECKPOINT + " is missing";
        } catch (Checkpoints.Damaged e) {
            problem = CHECKPOINT + " is damaged (" + e.reason() + ")";
        }
        if (!fromSnapshot) {
            throw new IllegalArgumentException(dir + ": " + problem + ", so the run cannot go on where it stopped (nothing "
                    + "was changed); add --from-snapshot to go on from its newest intact earlier checkpoint or policy snapshot");
        }
        ResumePoint.Found fallback = ResumePoint.fallback(dir, config, identity, envs, notes);
        if (fallback == null) {
            throw new IllegalArgumentException(dir + ": " + problem + " and the run has no intact earlier checkpoint ("
                    + PREVIOUS_CHECKPOINT + ") or policy snapshot (" + SNAPSHOTS + "/episode-N.json) to go on from");
        }
        notes.accept(dir + ": " + problem + "; going on from " + fallback.what());
        sweepTemporaryFiles(dir);
        ObjectNode record = Json.mapper().createObjectNode();
        record.put("from", fallback.what());
        record.put("episodes", fallback.trainer().episodes());
        record.put("because", problem);
        record.put("at", LocalDateTime.now().toString());
        ObjectNode runJson = (ObjectNode) Json.load(dir.resolve(RUN_JSON)).node();
        runJson.withArray("fallbacks").add(record);
        Outputs.writeJson(dir.resolve(RUN_JSON), runJson);
        return new TrainRun(dir, config, envs, rollouts, fallback.trainer());
    }

    /**
     * What a checkpoint of the run in {@code dir} must say it belongs to: the task, the object,
     * the SHA-256 of the config (without its episode budget, which a resume with --episodes
     * raises) and the run's id (run.json's, the folder's name when the run started).
     */
    static ObjectNode identity(Path dir, TrainConfig config) {
        ObjectNode id = Json.mapper().createObjectNode();
        id.put("task", config.run().task());
        id.put("object", config.run().object());
        ObjectNode withoutBudget = config.toJson();
        if (withoutBudget.get("training") instanceof ObjectNode training) {
            training.remove("episodes");
        }
        id.put("config", ReadLog.sha256(Json.pretty(withoutBudget).getBytes(StandardCharsets.UTF_8)));
        Path runJson = dir.resolve(RUN_JSON);
        Json started = Files.isRegularFile(runJson) ? Json.load(runJson) : null;
        id.put("run", started != null && started.has(RUN_ID) ? started.string(RUN_ID) : dir.getFileName().toString());
        return id;
    }

    /** The learner of a run's first episode: as {@link #start} made it, from the dataset or policy copied into the run. */
    private static Trainer initialTrainer(Path dir, TrainConfig config, ThrowEnvFactory envs) throws IOException {
        Path dataset = dir.resolve(INIT_DATASET);
        Path policy = dir.resolve(INIT_POLICY);
        return freshTrainer(config, envs, Files.isRegularFile(dataset) ? readDataset(dataset, envs) : null,
                Files.isRegularFile(policy) ? initPolicy(policy, config, envs) : null);
    }

    /** Deletes what writes killed in the run's folders left behind ({@link Outputs}). */
    private static void sweepTemporaryFiles(Path dir) throws IOException {
        Outputs.sweep(dir);
        Outputs.sweep(dir.resolve(SNAPSHOTS));
    }

    /**
     * This run with its budget raised to {@code episodes} ({@link #extend}, which records it in
     * the folder); to be called on a run just resumed, before it trains.
     */
    public TrainRun extendedTo(long episodes, ObjectNode provenance) throws IOException {
        TrainConfig extended = extend(dir, episodes, provenance);
        return new TrainRun(dir, extended, envs, rollouts, trainer.withConfig(extended.learner()));
    }

    public Path dir() {
        return dir;
    }

    public Trainer trainer() {
        return trainer;
    }

    /** Trains until the configured number of episodes, printing progress to {@code out}. */
    public void run(PrintStream out) throws IOException {
        run(out, Long.MAX_VALUE);
    }

    /**
     * Trains until the configured number of episodes or until {@code sessionEpisodes} more
     * episodes have been played (whichever comes first), then checkpoints: a long run can be
     * split over several invocations of train with {@link #resume}.
     */
    public void run(PrintStream out, long sessionEpisodes) throws IOException {
        long budget = Math.min(config.learner().training().episodes(),
                sessionEpisodes > Long.MAX_VALUE - trainer.episodes() ? Long.MAX_VALUE : trainer.episodes() + sessionEpisodes);
        int every = config.learner().training().checkpointEveryEpisodes();
        Progress progress = new Progress(out, config.learner().training().episodes(), trainer.episodes(),
                config.run().progressSeconds());
        out.printf(Locale.ROOT, "training %s (%s task, %s) in %s: episodes %d..%d of %d, %d at a time on %d workers%n",
                config.run().name(), config.run().task(), config.run().object(), dir, trainer.episodes() + 1, budget,
                config.learner().training().episodes(),
                config.learner().training().parallelEpisodes(), rollouts.workers());
        try (Stop.Watch watch = Stop.watch(); MetricsCsv csv = MetricsCsv.open(dir.resolve(METRICS), trainer.episodes())) {
            TrainingListener listener = new TrainingListener() {
                @Override
                public void onEpisode(EpisodeStats s) {
                    csv.onEpisode(s);
                    progress.onEpisode(s);
                }
            };
            boolean saved = false;
            while (trainer.episodes() < budget) {
                long before = trainer.episodes();
                try {
                    Stop.check("");
                    trainer.runRound(this::play, listener, (int) (budget - trainer.episodes()));
                } catch (Stop.Stopped stopped) {
                    throw stopped(stopped);
                }
                saved = every > 0 && trainer.episodes() / every != before / every;
                if (saved) {
                    saveCheckpoint();
                }
            }
            if (!saved) {
                saveCheckpoint();
            }
        }
        progress.finish();
        out.println("wrote " + dir.resolve(POLICY) + ", " + CHECKPOINT + ", " + METRICS + ", learning.png, losses.png");
    }

    /**
     * A stop request seen between rounds or during one (whose episodes are then dropped: they are
     * played again, the same, on resume): the learner as the last finished round left it is
     * checkpointed, unless its checkpoint is there already (or it played no episode yet).
     */
    private Stop.Stopped stopped(Stop.Stopped request) throws IOException {
        if (trainer.episodes() != checkpointed) {
            saveCheckpoint();
        }
        return new Stop.Stopped(request.signal(), trainer.episodes() > 0 ? "a checkpoint at episode " + trainer.episodes() + " is in "
                + dir + " (train --resume " + dir + " goes on from it)" : "no episode was finished; train --resume " + dir
                + " starts the run again");
    }

    /** A round's episodes on the rollout workers, each playing on an environment over its own simulator. */
    private List<EpisodePlayer.Episode> play(Policy snapshot, List<EpisodePlayer.Request> requests) {
        return rollouts.run(requests.size(), sim -> {
            ThrowEnv env = envs.create(sim);
            return i -> EpisodePlayer.play(env, requests.get(i), snapshot::act, config.learner().exploration(), t -> { });
        });
    }

    /** The learner, its policy as a throw policy file, and the curves so far. */
    private void saveCheckpoint() throws IOException {
        Path checkpoint = dir.resolve(CHECKPOINT);
        if (Files.exists(checkpoint)) {
            Outputs.keepCopy(checkpoint, dir.resolve(PREVIOUS_CHECKPOINT));
        }
        trainer.checkpoint(checkpoint, identity(dir, config));
        checkpointed = trainer.episodes();
        ObjectNode provenance = Json.mapper().createObjectNode();
        provenance.put("run", dir.getFileName().toString());
        provenance.put("episodes", trainer.episodes());
        provenance.put("decisions", trainer.steps());
        provenance.put("seed", config.learner().seed());
        provenance.setAll(startedBy); // how to train it again
        provenance.set("config", config.toJson());
        Policy actor = trainer.agent().policy(config.run().task() + " task, " + config.run().object() + ", run "
                + dir.getFileName() + ", episode " + trainer.episodes(), "ThrowSpace, see throwSpace");
        ThrowPolicyFile file = new ThrowPolicyFile(config.run().task(), config.run().object(), envs.state().encoding(), envs.space(), actor, provenance);
        file.save(dir.resolve(POLICY));
        file.save(dir.resolve(SNAPSHOTS).resolve(String.format(Locale.ROOT, "episode-%05d.json", trainer.episodes())));
        List<EpisodeStats> stats = MetricsCsv.read(dir.resolve(METRICS));
        String title = config.run().task() + " task, " + config.run().object() + " (" + config.run().name() + ", seed "
                + config.learner().seed() + ")";
        LearningCurves.plotRewards(dir.resolve("learning.png"), stats, "Learning curve: " + title);
        LearningCurves.plotLosses(dir.resolve("losses.png"), stats, "Losses: " + title);
    }

    /** A progress line at most every few seconds: episodes, rewards, Q0, drops, speed and ETA. */
    private static final class Progress {
        private final PrintStream out;
        private final int budget;
        private final long startEpisode;
        private final double everySeconds;
        private final long t0 = System.nanoTime();
        private long lastPrint;
        private EpisodeStats last;
        private int windowEpisodes;
        private int windowTerminal;

        Progress(PrintStream out, int budget, long startEpisode, double everySeconds) {
            this.out = out;
            this.budget = budget;
            this.startEpisode = startEpisode;
            this.everySeconds = everySeconds;
            this.lastPrint = t0;
        }

        void onEpisode(EpisodeStats s) {
            last = s;
            windowEpisodes++;
            windowTerminal += s.terminal() ? 1 : 0;
            if ((System.nanoTime() - lastPrint) * 1e-9 >= everySeconds) {
                print();
            }
        }

        void finish() {
            if (last != null && windowEpisodes > 0) {
                print();
            }
        }

        private void print() {
            long now = System.nanoTime();
            double elapsed = (now - t0) * 1e-9;
            double rate = (last.episode() - startEpisode) / Math.max(elapsed, 1e-9);
            double eta = (budget - last.episode()) / Math.max(rate, 1e-9);
            int width = 24, filled = (int) Math.round(width * (double) last.episode() / budget);
            out.printf(Locale.ROOT, "[%s%s] %d/%d episodes  %d decisions  reward %.2f  average %.2f  Q0 %.2f  drops %.0f%%"
                    + "  %.1f episodes/min  ETA %s%n", "#".repeat(filled), ".".repeat(width - filled), last.episode(), budget,
                    last.totalSteps(), last.reward(), last.averageReward(), last.q0(), 100.0 * windowTerminal / windowEpisodes,
                    60 * rate, clock(eta));
            lastPrint = now;
            windowEpisodes = 0;
            windowTerminal = 0;
        }

        private static String clock(double seconds) {
            long s = Math.round(seconds);
            return String.format(Locale.ROOT, "%d:%02d:%02d", s / 3600, (s / 60) % 60, s % 60);
        }
    }
}
