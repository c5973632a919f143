package handsim.app;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.cards.sleight.CardSleight;
import handsim.cards.sleight.SleightObjective;
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
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code handsim cards optimize}: a TPE or MOTPE study of a card sleight (thesis 3.2.4, Fig. 4.9,
 * 4.11), kept in a folder that the same command resumes after a kill, with the chosen trial
 * replayed into {@code chosen/} (its trajectory, frames and a strip).
 */
@Command(name = "optimize", mixinStandardHelpOptions = true,
        description = "Search a sleight's bone trajectory with TPE / MOTPE (Optuna 3.6.1's semantics): trials as JSON, resumable after a "
                + "kill (run the same command again), the optimisation history (thesis Fig. 4.9), the Pareto front of several objectives "
                + "(Fig. 4.11), the chosen trial (the one closest to zero with each objective scaled by its tolerance) and its frames "
                + "and strip. Results do not depend on --workers.")
final class CardsOptimize implements Callable<Integer> {

    static final String CHOSEN_DIR = "chosen";

    @Option(names = "--sleight", required = true, paramLabel = "NAME", description = "the sleight to optimise: snap (Card Snapping, thesis 4.2.4) "
            + "or double-lift (Double Lift, thesis 4.2.5)")
    String sleight;

    @Option(names = "--trials", required = true, paramLabel = "N", description = "run until trials 0 .. N-1 have finished (the thesis ran 89 and 297)")
    int trials;

    @Option(names = "--seed", required = true, paramLabel = "S", description = "the study's seed")
    long seed;

    @Option(names = "--workers", paramLabel = "N", description = "trials run on N threads (default: the config's parallelTrials); "
            + "the results are the same for any N, and with --master")
    Integer workers;

    @Option(names = "--out", paramLabel = "DIR", description = "the study folder (default: runs/cards-optimize__SLEIGHT-MESH__SEED); "
            + "a folder holding a study resumes it")
    Path out;

    @Option(names = "--config", paramLabel = "FILE", description = "the study's objectives (with tolerances), search space, sampler "
            + "settings and parallelTrials (default: configs/cards/SLEIGHT-study.json)")
    Path config;

    @Option(names = "--sampler", paramLabel = "KIND", description = "independent or multivariate TPE (Optuna's multivariate=False / True) "
            + "instead of the config's choice; part of the study")
    String sampler;

    @Mixin
    CardsSceneOptions scene;

    @Mixin
    ClusterOptions cluster;

    @Option(names = "--set", paramLabel = "FILE.KEY=VALUE", description = "override a field of configs/cards/FILE.json (the sleight's, "
            + "materials, solver, budget), e.g. --set snap.trial.alphaTarget=4 or --set solver.parallel=false (repeatable; dotted "
            + "paths); part of the study, so a resume needs the same")
    List<String> overrides = List.of();

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException, InterruptedException {
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
        if (!handsim.cards.sleight.Sleights.NAMES.contains(sleight)) {
            throw new IllegalArgumentException("--sleight must be one of " + String.join(", ", handsim.cards.sleight.Sleights.NAMES)
                    + ", got \"" + sleight + "\"");
        }
        Path configFile = config != null ? config : CardsCommand.studyConfig(sleight);
        if (!Files.isRegularFile(configFile)) {
            throw new IllegalArgumentException("--config " + configFile + " is not a file");
        }
        StudyConfig studyConfig = withSampler(StudyConfig.load(configFile), sampler);
        CardSleight trial = CardsCommand.sleight(sleight, scene, RunOptions.keyValues(overrides));
        trial.checkSearchSpace(studyConfig, configFile.toString());
        Path dir = out != null ? out : Home.resolve("runs").resolve("cards-optimize__" + sleight + "-" + trial.meshName() + "__" + seed);
        new OutputPaths().heldFolder("--out", dir, studyOutputs(studyConfig)).check();

        ObjectNode provenance = Provenance.of(spec.commandLine().getParseResult().originalArgs());
        // a cluster is reached before the study folder is made: a master that cannot be used leaves nothing behind
        Study study;
        try (RemoteCalls calls = cluster.remote() ? cluster.connect("handsim cards optimize " + dir.getFileName()) : null) {
            study = Study.openOrCreate(dir, studyConfig, seed, trial.inputs(), provenance);
            if (studyConfig.multiObjective()) {
                study.displayObjectives(1000, "mm"); // Double Lift's objectives are lengths in metres
            }
            System.out.printf(Locale.ROOT, "handsim cards optimize: %s, %s fingertips (%d nodes, %d free), %s cards, %s%n", trial.title(),
                    trial.meshName(), trial.world().nodeCount(), trial.world().freeNodeCount(), trial.inputs().get("card").asText(),
                    studyConfig.sampler().multivariate() ? "multivariate TPE" : "independent TPE");
            if (calls != null) {
                // each executor builds the sleight from its documents and makes its start state once for the trials it runs
                int toRun = trials - (int) study.trials().stream().filter(t -> t.number() < trials).count();
                try (RemoteTrials remote = new RemoteTrials(calls, SleightObjective.of(trial), studyConfig, seed, toRun)) {
                    study.run(remote, trials, System.out);
                }
            } else {
                long h0 = System.nanoTime();
                trial.startState(trial.defaults());
                System.out.printf(Locale.ROOT, "start (warm-up checkpoint, shared by every trial): %.1f s wall%n", (System.nanoTime() - h0) * 1e-9);
                study.run(trial.objective(), trials, workers != null ? workers : studyConfig.parallelTrials(), System.out);
            }
        }

        TrialRecord chosen = study.chosen().orElse(null);
        if (chosen == null) {
            System.out.println("no trial completed: no trial to replay");
            return 1;
        }
        System.out.printf(Locale.ROOT, "chosen: trial %d, %s%s; params %s%n", chosen.number(), values(studyConfig, chosen),
                studyConfig.hasTolerances() ? (studyConfig.meets(chosen.values()) ? ", meets every tolerance" : ", MISSES a tolerance") : "",
                chosen.trialParams(studyConfig).values());
        replay(dir.resolve(CHOSEN_DIR), chosen, studyConfig, trial);
        System.out.println("study folder: " + dir + " (" + Study.BEST_FILE + ", history*.png" + (studyConfig.multiObjective() ? ", pareto.png" : "")
                + ", " + CHOSEN_DIR + "/)");
        return 0;
    }

    /** What a study folder holds: study.json, best.json, the trials, the history and Pareto figures, the chosen trial's recording. */
    static String[] studyOutputs(StudyConfig c) {
        List<String> names = new java.util.ArrayList<>(List.of(Study.STUDY_FILE, Study.BEST_FILE, Study.TRIALS_DIR + "/", CHOSEN_DIR + "/"));
        if (c.multiObjective()) {
            c.objectives().forEach(name -> names.add("history-" + name + ".png"));
            names.add("pareto.png");
        } else {
            names.add("history.png");
        }
        return names.toArray(String[]::new);
    }

    /** The config with independent or multivariate TPE as {@code kind} asks (null: as it is). */
    static StudyConfig withSampler(StudyConfig c, String kind) {
        if (kind == null) {
            return c;
        }
        if (!kind.equals("independent") && !kind.equals("multivariate")) {
            throw new IllegalArgumentException("--sampler must be independent or multivariate, got \"" + kind + "\"");
        }
        var s = c.sampler();
        return new StudyConfig(c.objectives(), c.directions(), c.tolerances(), c.params(), new handsim.cards.tpe.TpeSettings(s.nStartupTrials(),
                s.nEiCandidates(), s.considerPrior(), s.priorWeight(), s.considerMagicClip(), s.considerEndpoints(), kind.equals("multivariate")),
                c.parallelTrials());
    }

    static String values(StudyConfig c, TrialRecord t) {
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < c.objectives().size(); i++) {
            s.append(i == 0 ? "" : ", ").append(c.objectives().get(i)).append(' ').append(String.format(Locale.ROOT, "%.4g", t.values()[i]));
        }
        return s.toString();
    }

    /**
     * Runs the chosen trial again, recording it, into {@code chosenDir} (trajectory, frames, strip,
     * result.json with the trial's number); skipped when the folder already holds that trial.
     * Trials are deterministic, so the replay reproduces the recorded objectives bit for bit.
     */
    private void replay(Path chosenDir, TrialRecord chosen, StudyConfig studyConfig, CardSleight trial) throws IOException {
        Path result = chosenDir.resolve("result.json");
        boolean framesWanted = !scene.noFrames;
        if (Files.exists(result) && Json.load(result).integer("trial") == chosen.number()
                && (!framesWanted || Files.exists(chosenDir.resolve("strip.png")))) {
            System.out.println("chosen trial " + chosen.number() + " already recorded in " + chosenDir);
            return;
        }
        System.out.println("replaying chosen trial " + chosen.number() + " to record its frames...");
        Map<String, Double> p = chosen.trialParams(studyConfig).values();
        CardsRecording.Recorded run = CardsRecording.record(trial, p);
        boolean same = java.util.Arrays.equals(run.outcome().values(), chosen.values());
        if (!same) {
            System.out.printf(Locale.ROOT, "the replay's objectives %s differ from the trial's %s: the code or configs changed since the "
                    + "trial ran%n", java.util.Arrays.toString(run.outcome().values()), java.util.Arrays.toString(chosen.values()));
        }
        ObjectNode json = CardsRecording.resultJson(trial, p, run, studyConfig.objectives());
        json.put("trial", chosen.number());
        json.put("reproducesTrial", same);
        json.put("meetsTolerances", studyConfig.meets(run.outcome().values()));
        CardsRecording.write(chosenDir, run, json, CardViews.of(sleight, ViewerSession.config()), scene.frameWidth(), scene.height);
    }
}
