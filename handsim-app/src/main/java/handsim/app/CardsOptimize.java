package handsim.app;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.sleight.SnapObjective;
import handsim.cards.sleight.SnapParams;
import handsim.cards.sleight.SnapStudy;
import handsim.cards.sleight.SnapTrial;
import handsim.cards.study.RemoteTrials;
import handsim.cards.study.Study;
import handsim.cards.study.StudyConfig;
import handsim.cards.study.TrialRecord;
import handsim.config.Home;
import handsim.config.Json;
import handsim.rollout.RemoteCalls;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code handsim cards optimize}: a TPE study of a card sleight (thesis 3.2.4, Fig. 4.9), kept in
 * a folder that the same command resumes after a kill, with the best trial replayed into
 * {@code best/} (its trajectory, frames and a strip like thesis Fig. 4.8).
 */
@Command(name = "optimize", mixinStandardHelpOptions = true,
        description = "Search a sleight's bone trajectory with TPE (Optuna 3.6.1's semantics): trials as JSON, resumable after a kill "
                + "(run the same command again), the optimisation history (thesis Fig. 4.9), the best parameters, and the best "
                + "trial's frames and strip (thesis Fig. 4.8). Results do not depend on --workers.")
final class CardsOptimize implements Callable<Integer> {

    static final String BEST_DIR = "best";

    @Option(names = "--sleight", required = true, paramLabel = "NAME", description = "the sleight to optimise: snap (Card Snapping, thesis 4.2.4)")
    String sleight;

    @Option(names = "--trials", required = true, paramLabel = "N", description = "run until trials 0 .. N-1 have finished (the thesis ran 89)")
    int trials;

    @Option(names = "--seed", required = true, paramLabel = "S", description = "the study's seed")
    long seed;

    @Option(names = "--workers", paramLabel = "N", description = "trials run on N threads (default: the config's parallelTrials); "
            + "the results are the same for any N, and with --master")
    Integer workers;

    @Option(names = "--out", paramLabel = "DIR", description = "the study folder (default: runs/cards-optimize__SLEIGHT-MESH__SEED); "
            + "a folder holding a study resumes it")
    Path out;

    @Option(names = "--config", paramLabel = "FILE", description = "the study's search space, sampler settings and parallelTrials "
            + "(default: configs/cards/snap-study.json)")
    Path config;

    @Mixin
    CardsSceneOptions scene;

    @Mixin
    ClusterOptions cluster;

    @Option(names = "--set", paramLabel = "FILE.KEY=VALUE", description = "override a field of configs/cards/FILE.json (snap, materials, "
            + "solver), e.g. --set snap.trial.alphaTarget=4 or --set solver.parallel=false (repeatable; dotted paths); part of "
            + "the study, so a resume needs the same")
    List<String> overrides = List.of();

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException, InterruptedException {
        if (!sleight.equals("snap")) {
            throw new IllegalArgumentException("--sleight must be snap, got \"" + sleight + "\"");
        }
        if (trials < 1) {
            throw new IllegalArgumentException("--trials must be >= 1, got " + trials);
        }
        if (workers != null && workers < 1) {
            throw new IllegalArgumentException("--workers must be >= 1, got " + workers);
        }
        scene.checkFrameSize();
        cluster.validate();
        if (workers != null && cluster.remote()) {
            throw new IllegalArgumentException("--workers goes without --master: the cluster's cores run the trials");
        }
        Path configFile = config != null ? config : Home.resolve("configs/cards/snap-study.json");
        if (!Files.isRegularFile(configFile)) {
            throw new IllegalArgumentException("--config " + configFile + " is not a file");
        }
        StudyConfig studyConfig = StudyConfig.load(configFile);
        SnapTrial trial = SnapTrial.fromConfigs(Home.root(), scene.mesh, scene.card, RunOptions.keyValues(overrides));
        SnapStudy.check(studyConfig, trial.scene().config().duration(), configFile.toString());
        Path dir = out != null ? out : Home.resolve("runs").resolve("cards-optimize__" + sleight + "-" + trial.scene().config().meshName() + "__" + seed);
        new OutputPaths().heldFolder("--out", dir, Study.STUDY_FILE, Study.BEST_FILE, "history.png", Study.TRIALS_DIR + "/",
                BEST_DIR + "/").check();

        ObjectNode provenance = Provenance.of(spec.commandLine().getParseResult().originalArgs());
        // a cluster is reached before the study folder is made: a master that cannot be used leaves nothing behind
        Study study;
        try (RemoteCalls calls = cluster.remote() ? cluster.connect("handsim cards optimize " + dir.getFileName()) : null) {
            study = Study.openOrCreate(dir, studyConfig, seed, trial.inputs(), provenance);
            System.out.printf(Locale.ROOT, "handsim cards optimize: Card Snapping, %s fingertips (%d nodes, %d free), %s cards, alpha_target %s "
                    + "deg%n", trial.scene().config().meshName(), trial.scene().world().nodeCount(), trial.scene().world().freeNodeCount(),
                    trial.inputs().get("card").asText(), trial.scene().config().alphaTargetDegrees());
            if (calls != null) {
                // each executor builds the trial from its documents and simulates the hold once for the trials it runs
                int toRun = trials - (int) study.trials().stream().filter(t -> t.number() < trials).count();
                try (RemoteTrials remote = new RemoteTrials(calls, SnapObjective.of(trial), studyConfig, seed, toRun)) {
                    study.run(remote, trials, System.out);
                }
            } else {
                long h0 = System.nanoTime();
                trial.heldState();
                System.out.printf(Locale.ROOT, "hold (warm-up checkpoint, shared by every trial): %.1f s wall%n", (System.nanoTime() - h0) * 1e-9);
                study.run(SnapStudy.objective(trial), trials, workers != null ? workers : studyConfig.parallelTrials(), System.out);
            }
        }

        TrialRecord best = study.best().orElse(null);
        if (best == null) {
            System.out.println("no trial completed: no best trial to replay");
            return 1;
        }
        System.out.printf(Locale.ROOT, "best: trial %d, objective %.4g deg, alpha_end %.4g deg; params %s%n", best.number(), best.values()[0],
                best.info().get("alphaEnd"), best.trialParams(studyConfig).values());
        replayBest(dir.resolve(BEST_DIR), best, studyConfig, trial);
        System.out.println("study folder: " + dir + " (" + Study.BEST_FILE + ", history.png, " + BEST_DIR + "/)");
        return 0;
    }

    /**
     * Runs the best trial again, recording it, into {@code bestDir} (trajectory, frames, strip,
     * result.json with the trial's number); skipped when the folder already holds that trial.
     * Trials are deterministic, so the replay reproduces the recorded objective bit for bit.
     */
    private void replayBest(Path bestDir, TrialRecord best, StudyConfig studyConfig, SnapTrial trial) throws IOException {
        Path result = bestDir.resolve("result.json");
        boolean framesWanted = !scene.noFrames;
        if (Files.exists(result) && Json.load(result).integer("trial") == best.number()
                && (!framesWanted || Files.exists(bestDir.resolve("strip.png")))) {
            System.out.println("best trial " + best.number() + " already recorded in " + bestDir);
            return;
        }
        System.out.println("replaying best trial " + best.number() + " to record its frames...");
        SnapParams p = SnapStudy.params(best.trialParams(studyConfig));
        CardsCommand.Recorded run = CardsCommand.record(trial, p);
        double recorded = best.values()[0];
        boolean same = Double.compare(run.result().objective(), recorded) == 0;
        if (!same) {
            System.out.printf(Locale.ROOT, "the replay's objective %.17g differs from the trial's %.17g: the code or configs changed "
                    + "since the trial ran%n", run.result().objective(), recorded);
        }
        ObjectNode json = CardsCommand.resultJson(run.result(), p, trial);
        json.put("trial", best.number());
        json.put("reproducesTrial", same);
        CardsCommand.writeRecording(bestDir, run, json, scene.frameWidth(), scene.height);
    }
}
