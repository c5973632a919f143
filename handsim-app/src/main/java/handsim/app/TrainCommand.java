package handsim.app;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.ConfigSet;
import handsim.config.Json;
import handsim.control.ControllerConfig;
import handsim.report.Outputs;
import handsim.rollout.Rollouts;
import handsim.sim.ObjectSpec;
import handsim.sim.Simulator;
import handsim.spec.RunConfigs;
import handsim.task.StateVector;
import handsim.task.ThrowTask;
import handsim.taskdef.TaskDefinition;
import handsim.train.ThrowEnv;
import handsim.train.ThrowEnvFactory;
import handsim.train.TrainConfig;
import handsim.train.TrainRun;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code handsim train}: a DDPG training run of a throw task in a run folder, or the
 * continuation of one from its last checkpoint.
 */
@Command(name = "train", mixinStandardHelpOptions = true,
        description = "Train the THROW of a task with DDPG (paper sec. 3.7, 4). Writes runs/<task>__<name>__<seed>__<time>/ "
                + "with config.json, run.json, metrics.csv, checkpoint.zip, learning.png, losses.png and policy.json; "
                + "a run killed at any moment continues with --resume.")
final class TrainCommand implements Callable<Integer> {

    /**
     * When set, the file {@code train} writes its run folder's path to as soon as the folder
     * exists: the launcher ({@code scripts/handsim}) reads it to resume the run after the JVM
     * dies in native code.
     */
    static final String RUN_DIR_FILE_PROPERTY = "handsim.runDirFile";

    @Mixin
    RunOptions run;

    @Option(names = "--from-snapshot", description = "with --resume, when the run's checkpoint is missing or damaged: go on "
            + "from its newest intact earlier checkpoint (checkpoint-previous.zip), else from its newest intact policy "
            + "snapshot (policies/episode-N.json: the actor with a new critic and an empty replay buffer); recorded in run.json")
    boolean fromSnapshot;

    @Option(names = "--init-actor", paramLabel = "DATASET_OR_ACTOR",
            description = "start the actor fitted to a warm-start dataset (dataset.csv, or the warmstart run folder "
                    + "holding it) with the config's pretrain settings, or as a trained throw policy (a .json policy "
                    + "file of the same task, object and state, e.g. to fine-tune it), instead of from scratch")
    Path initActor;

    @Option(names = "--episodes", paramLabel = "N",
            description = "with --resume: raise the run's episode budget to N and go on training (a finished run "
                    + "continues exactly as one configured with N episodes from the start; recorded in run.json)")
    Long episodes;

    @Option(names = "--session-episodes", paramLabel = "N",
            description = "stop (with a checkpoint) after N more episodes; --resume goes on from there")
    Long sessionEpisodes;

    @Override
    public Integer call() throws IOException {
        run.validate();
        if (sessionEpisodes != null && sessionEpisodes < 1) {
            throw new IllegalArgumentException("--session-episodes must be at least 1, got " + sessionEpisodes);
        }
        if (initActor != null && run.resume != null) {
            throw new IllegalArgumentException("--init-actor starts a new run: a resumed run already has its actor");
        }
        if (fromSnapshot && run.resume == null) {
            throw new IllegalArgumentException("--from-snapshot goes with --resume RUN_DIR");
        }
        if (episodes != null && run.resume == null) {
            throw new IllegalArgumentException("--episodes extends a run given with --resume; a new run sets its budget "
                    + "with --set training.episodes=N");
        }
        if (run.resume != null) {
            RunFolders.hold("--resume", run.resume); // one process at a time on a run folder
        }
        TrainConfig c = run.resume == null ? TrainConfig.parse(run.configFile()) : TrainRun.savedConfig(run.resume);
        RunConfigs configs = run.resume == null ? configs(c.run()) : recorded(run.resume, c.run());
        ThrowEnvFactory envs = environments(c.run(), configs);
        try (Rollouts<Simulator> rollouts = Wiring.rollouts(configs.model(), configs.sim(), c.run().workers())) {
            TrainRun training = run.resume != null ? resumed(envs, rollouts) : started(c, envs, rollouts);
            recordSpec(training.dir(), configs);
            tellLauncher(training.dir());
            training.run(System.out, sessionEpisodes != null ? sessionEpisodes : Long.MAX_VALUE);
        }
        return 0;
    }

    /** Writes the run folder's absolute path to the file named by {@link #RUN_DIR_FILE_PROPERTY}, if any. */
    private static void tellLauncher(Path dir) throws IOException {
        String file = System.getProperty(RUN_DIR_FILE_PROPERTY);
        if (file != null) {
            Outputs.writeString(Path.of(file), dir.toAbsolutePath().toString());
        }
    }

    /** Where a run folder records the configuration documents its run read ({@link ConfigSet#toJson}). */
    static final String SPEC = "spec.json";

    /**
     * The configs of the run in {@code dir}: the documents its folder records ({@link #SPEC}), so
     * that a resumed run plays in the world it began in; the project's files for a folder without
     * the record.
     */
    static RunConfigs recorded(Path dir, TrainConfig.Run run) {
        Path spec = dir.resolve(SPEC);
        return Files.isRegularFile(spec) ? new RunConfigs(ConfigSet.replaying(Json.load(spec))) : configs(run);
    }

    /**
     * Records in {@code dir} every configuration document the run has read; a run that replays
     * its folder's record ({@link #recorded}) leaves it as it is, since it is this run's input.
     */
    static void recordSpec(Path dir, RunConfigs configs) throws IOException {
        if (!configs.files().replays()) {
            Outputs.writeJson(dir.resolve(SPEC), configs.files().toJson());
        }
    }

    /**
     * The project's configs with the fields of the task's file that the run changes ({@link
     * TrainConfig.Run#taskSet}) and the physics' stepper it names ({@link TrainConfig.Run#stepper}).
     */
    static RunConfigs configs(TrainConfig.Run run) {
        return RunConfigs.ofProject(run.task(), run.taskSet(), run.stepper());
    }

    /** The environments of a run: its task (as {@code configs} define it) and object with the controller, launch and episode configs. */
    static ThrowEnvFactory environments(TrainConfig.Run run, RunConfigs configs) {
        TaskDefinition task = configs.task(run.task());
        ThrowTask probe = task.newTask(run.object()); // an object the task cannot take fails here
        ControllerConfig cc = configs.controller();
        ObjectSpec object = configs.object(run.object());
        return new ThrowEnvFactory(run.task(), object, () -> task.newTask(run.object()), cc, configs.limits(), configs.launches(),
                probe.throwSpace(cc.throwSpace()),
                new ThrowEnv.Settings(run.firstCatchAttempts(), run.divergedReward(), run.spinShaping(), run.endAtFailedThrow()),
                new StateVector(run.state(), object.longAxis(), StateVector.Hand.of(configs.model())));
    }

    /** A new run in a folder of its own (given up again if the run cannot start). */
    private TrainRun started(TrainConfig c, ThrowEnvFactory envs, Rollouts<Simulator> rollouts) throws IOException {
        Path dir = RunFolders.claim(run.runs, "--runs", c.run().task(), c.run().name(), c.learner().seed());
        try {
            return TrainRun.start(dir, c, envs, rollouts, provenance(c), initActor);
        } catch (IOException | RuntimeException e) {
            RunFolders.release(dir);
            throw e;
        }
    }

    /** The run of --resume, its budget raised to --episodes if given (recorded only once it can go on). */
    private TrainRun resumed(ThrowEnvFactory envs, Rollouts<Simulator> rollouts) throws IOException {
        TrainRun resumed = TrainRun.resume(run.resume, envs, rollouts, fromSnapshot, note -> System.out.println("handsim train: " + note));
        return episodes != null ? resumed.extendedTo(episodes, extension()) : resumed;
    }

    /** What {@code run.json} records about an extension of the run's budget. */
    private ObjectNode extension() {
        ObjectNode p = Json.mapper().createObjectNode();
        p.put("command", "scripts/handsim train --resume " + run.resume + " --episodes " + episodes);
        p.put("commit", Provenance.gitCommit());
        p.put("at", LocalDateTime.now().toString());
        return p;
    }

    /** What a run folder records about how the run was made. */
    private ObjectNode provenance(TrainConfig c) {
        return run.provenance("train", initActor, c.learner().seed());
    }
}
