package handsim.app;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.learn.Dagger;
import handsim.rollout.Rollouts;
import handsim.sim.Simulator;
import handsim.spec.RunConfigs;
import handsim.train.DaggerRun;
import handsim.train.DaggerRunConfig;
import handsim.train.ThrowEnvFactory;
import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code handsim dagger}: the learned throw imitates the twin-world teacher by dataset
 * aggregation (handsim.learn.Dagger), in a run folder, or the continuation of one.
 */
@Command(name = "dagger", mixinStandardHelpOptions = true,
        description = "Train the THROW of a task by DAgger: each round plays episodes with the learner, a teacher that tries "
                + "throws in a twin world labels every decision the learner makes (all, or those from one rest of the object: "
                + "learnerThrows) with the nearest throw that works (the learner's own when it does), and a fresh actor is fitted "
                + "to all labels so far. Writes runs/dagger__<name>__<seed>__<time>/ with config.json, run.json, "
                + "demonstrations.csv, rounds.csv, policies/round-NN.json and policy.json; a run killed at any moment "
                + "continues with --resume. The teacher is needed for training only: the policy throws alone.")
final class DaggerCommand implements Callable<Integer> {

    @Mixin
    RunOptions run;

    @Option(names = "--init-actor", paramLabel = "POLICY",
            description = "round 0's learner: a throw policy file of the same task, object and state (default: the task's nominal throw)")
    Path initActor;

    @Mixin
    ClusterOptions cluster;

    @Override
    public Integer call() throws IOException {
        run.validate();
        cluster.validate();
        if (initActor != null && run.resume != null) {
            throw new IllegalArgumentException("--init-actor starts a new run: a resumed run keeps the start saved in its folder");
        }
        if (run.resume != null) {
            RunFolders.hold("--resume", run.resume); // one process at a time on a run folder
        }
        Json file = run.resume == null ? run.configFile() : null;
        DaggerRunConfig c = run.resume == null ? DaggerRunConfig.parse(file) : DaggerRun.savedConfig(run.resume);
        RunConfigs configs = run.resume == null ? TrainCommand.configs(c.run()) : TrainCommand.recorded(run.resume, c.run());
        ThrowEnvFactory envs = TrainCommand.environments(c.run(), configs);
        // a cluster is reached before the run folder is made: a master that cannot be used leaves nothing behind
        try (Rollouts<Simulator> rollouts = cluster.remote() ? ClusterWiring.rollouts(cluster, configs, "handsim dagger " + c.run().name()
                + " seed " + c.learner().seed()) : Wiring.rollouts(configs.model(), configs.sim(), c.run().workers())) {
            DaggerRun dagger = run.resume != null ? DaggerRun.resume(run.resume, envs, rollouts, Wiring::twinSimulator)
                    : started(file, c, envs, rollouts);
            TrainCommand.recordSpec(dagger.dir(), configs);
            if (cluster.remote()) {
                dagger.onCluster(PortableDagger.shipper(dagger.dir(), configs));
            }
            try {
                dagger.run(System.out);
            } catch (Dagger.TooFewLabels e) {
                throw new RunFailed(e.getMessage() + "; the episodes played are kept in " + dagger.dir() + ", and a new run with more "
                        + "decisions (dagger.episodesPerRound, dagger.maxDecisionsPerEpisode" + (c.learnerThrows() == null ? ""
                                : ", learnerThrows.maxLoops or another learnerThrows.rest") + ") gives more labels");
            }
        }
        return 0;
    }

    /** A new run in a folder of its own (given up again if the run cannot start). */
    private DaggerRun started(Json file, DaggerRunConfig c, ThrowEnvFactory envs, Rollouts<Simulator> rollouts) throws IOException {
        Path dir = RunFolders.claim(run.runs, "--runs", "dagger", c.run().name(), c.learner().seed());
        try {
            return DaggerRun.start(dir, file, envs, rollouts, Wiring::twinSimulator, provenance(c), initActor);
        } catch (IOException | RuntimeException e) {
            RunFolders.release(dir);
            throw e;
        }
    }

    /** What a run folder records about how the run was made. */
    private ObjectNode provenance(DaggerRunConfig c) {
        return run.provenance("dagger", initActor, c.learner().seed());
    }
}
