package handsim.app;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.evaluation.EpisodeJournal;
import handsim.evaluation.EvaluationRequest;
import handsim.evaluation.EvaluationSetup;
import handsim.evaluation.TaskEvaluation;
import handsim.report.Outputs;
import handsim.rollout.LocalRollouts;
import handsim.rollout.Rollouts;
import handsim.sim.Simulator;
import handsim.spec.RunConfigs;
import handsim.taskdef.TaskDefinition;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code handsim evaluate}: seeded catch-and-throw episodes of a task with the nominal or a
 * learned controller, with the per-loop figures and the paper's: the height errors and their
 * histogram (Fig. 5), the box trials and their success map (Fig. 8), the flip-and-catch loops in
 * a row (sec. 4.4). The options and their wiring; the evaluations are {@link TaskEvaluation}s.
 */
@Command(name = "evaluate", mixinStandardHelpOptions = true,
        description = "Run seeded catch-and-throw episodes of a task: an object is thrown toward the hand (configs/launch.json), "
                + "then the arm catches and throws. height: --episodes episodes of up to --loops throws, a new random target "
                + "apex every throw (or --throw-height, or --goals); summary with the height errors and their histogram. "
                + "box: --tests box positions, each a trial that succeeds after the hit-and-catch loops in a row of "
                + "configs/tasks/box.json; summary with the success rate by distance from the region's centre and a success "
                + "map. flip: --episodes episodes that run until a throw fails to flip or is dropped (at most --loops); "
                + "summary with the consecutive flip-and-catch loops.")
final class EvaluateCommand implements Callable<Integer> {

    @Mixin
    ControllerOptions who;

    @Mixin
    EpisodeOptions episodeOptions;

    @Option(names = "--loops", paramLabel = "N", description = "height: throws to attempt per episode after the first catch "
            + "(default: configs/tasks/height.json evaluationThrows); flip: the most flip-and-catch loops an episode runs to "
            + "(default: configs/tasks/flip.json evaluationLoops); --copies: throws per copy (default: configs/evaluation.json "
            + "sensitivityThrows)")
    Integer loopsOption;

    @Option(names = "--episodes", defaultValue = "1", description = "height, flip: episodes, seeded --seed, --seed+1, ...")
    int episodes;

    @Option(names = "--tests", defaultValue = "538", description = "box: box positions to try (default: ${DEFAULT-VALUE}, the paper's)")
    int tests;

    @Option(names = "--throw-height", paramLabel = "H",
            description = "height: every throw aims at H m (default: a random target per throw from configs/tasks/height.json)")
    Double throwHeight;

    @Option(names = "--goals", paramLabel = "FILE",
            description = "goals to use instead of seeded ones: {\"heights\": [h, ...]} (one per throw, in turn) or "
                    + "{\"boxes\": [[x, y, z], ...]} (one per trial, m, world)")
    Path goals;

    @Option(names = "--workers", paramLabel = "N",
            description = "episodes run in parallel, each worker with its own engine (default: all local cores); "
                    + "results do not depend on it")
    Integer workers;

    @Option(names = "--copies", paramLabel = "N",
            description = "height, flip: instead of the summary, run every episode N times, copy 0 as seeded and the others with "
                    + "the launch velocity nudged by --nudge in a random direction, for --loops throws whether they succeed or "
                    + "not, and report how far each throw's apex and flight rotation spread across the copies, and each copy's throws, drops "
                    + "and (height) mean |error|")
    Integer copies;

    @Option(names = "--nudge", paramLabel = "V", defaultValue = "1e-9",
            description = "the launch velocity nudge of --copies (m/s, default: ${DEFAULT-VALUE})")
    double nudge;

    @Option(names = "--json", paramLabel = "FILE", description = "write the summary as JSON, with its provenance (commit, "
            + "command line, SHA-256 of every config, model and policy file read); while the run goes, each finished episode is "
            + "kept in FILE.episodes.jsonl, and the same command run again after a kill runs only the episodes not yet finished")
    Path json;

    @Option(names = "--csv", paramLabel = "FILE", description = "write one row per loop (height, flip) or trial (box) as CSV")
    Path csv;

    @Option(names = "--plot", paramLabel = "FILE",
            description = "the histogram (height), success map (box) or loops per episode (flip, with the throws by flight rotation "
                    + "beside it as NAME-rotation.png) PNG, or with --copies the spread by throw (default: next to --json, same name "
                    + "with .png)")
    Path plot;

    @Option(names = "--spec", paramLabel = "FILE", description = "repeat a recorded run: the spec of an evaluate JSON (or a spec "
            + "file alone), with its options, configuration, goals and policies as recorded; only --json, --csv, --plot, --workers and "
            + "--export go with it")
    Path specFile;

    @Option(names = "--export", paramLabel = "FILE",
            description = "with --episodes 1 (box: --tests 1): also write the episode's animation (FILE.glb, FILE.gltf or FILE.bvh; see export)")
    Path export;

    @Mixin
    ClusterOptions cluster;

    @Spec
    CommandSpec spec;

    /** The options a recorded run's spec decides: refused beside --spec. */
    private static final List<String> RECORDED = List.of("--task", "--controller", "--object", "--seed", "--policy", "--opening-policy",
            "--rest-policy", "--plan", "--task-set", "--loops", "--episodes", "--tests", "--throw-height", "--goals", "--copies", "--nudge",
            "--stepper");

    @Override
    public Integer call() throws Exception {
        String commit = Provenance.gitCommit(); // the code this run begins with
        EvaluateSpec run = resolve();
        RunExport exported = validate(run);
        RunConfigs configs = run.configs();
        EvaluationRequest request = run.request(csv, plot, exported != null);
        TaskDefinition definition = run.definition();
        definition.check(request); // options the task does not take, a bad goals file: refused before anything is written
        EvaluationSetup setup = run.setup(exported, System.out);
        configs.model(); // the engine's documents too: every document read before the journal records them
        configs.sim();
        ObjectNode record = run.toJson();
        // a cluster is reached before the journal is made: a master that cannot be used leaves nothing behind
        Rollouts<Simulator> remote = cluster.remote() ? ClusterWiring.evaluation(cluster, run) : null;
        EpisodeJournal journal = json == null ? null : ClusterWiring.closingOnFailure(remote,
                () -> EvaluationJournals.open(json, record, commit, spec.commandLine().getParseResult().originalArgs()));
        long t0 = System.nanoTime();
        ObjectNode out = summaryHead(run);
        try (Rollouts<Simulator> rollouts = remote != null ? remote : Wiring.rollouts(configs.model(), configs.sim(), workers)) {
            definition.evaluation(request, EvaluationJournals.with(setup, journal)).run(rollouts, out);
        }
        out.put("wall_s", (System.nanoTime() - t0) / 1e9);
        if (exported != null) {
            exported.write("handsim evaluate: " + run.task() + " task, " + run.object() + ", " + request.controllerLabel()
                    + " controller, seed " + run.seed());
        }
        if (journal != null) {
            out.put("episodes_resumed", journal.resumed());
        }
        ObjectNode provenance = Provenance.of(spec.commandLine().getParseResult().originalArgs(), commit);
        if (journal != null) {
            // a resumed run's episodes may come from more than one commit: say which ran how many
            journal.episodesByCommit().forEach(provenance.putObject("episodes_by_commit")::put);
        }
        out.set("provenance", provenance);
        out.set("spec", run.toJson());
        if (json != null) {
            Outputs.writeJson(json, out);
            System.out.println("wrote " + json);
            journal.delete();
        }
        return 0;
    }

    /** The run asked for: the spec of --spec, or the one the options give. */
    private EvaluateSpec resolve() {
        if (specFile == null) {
            who.validate(); // a bad --stepper among them, refused before anything is written
            return EvaluateSpec.of(who, episodeOptions.object, episodeOptions.seed, loopsOption, episodes, tests, throwHeight, goals,
                    copies, nudge);
        }
        for (String option : RECORDED) {
            if (spec.commandLine().getParseResult().hasMatchedOption(option)) {
                throw new IllegalArgumentException(option + " goes without --spec: the recorded run decides it");
            }
        }
        return EvaluateSpec.read(specFile);
    }

    /** The summary's first fields: what was run. */
    private ObjectNode summaryHead(EvaluateSpec run) {
        ObjectNode out = JsonNodeFactory.instance.objectNode();
        out.put("task", run.task());
        out.put("controller", run.controller());
        out.put("planned", run.plan());
        if (run.policies().containsKey("policy")) {
            out.put("policy", run.policies().get("policy").toString());
            Path opening = run.policies().get("opening_policy");
            out.put("opening_policy", opening != null ? opening.toString() : null);
            Path rest = run.policies().get("rest_policy");
            out.put("rest_policy", rest != null ? rest.toString() : null);
        }
        out.put("object", run.object());
        out.put("stepper", run.configs().sim().stepper().label());
        out.set("controller_parts", run.controllerParts());
        if (!run.taskSet().isEmpty()) {
            out.set("task_set", run.toTaskSetJson());
        }
        out.put("seed", run.seed());
        out.put("workers", workers); // null on a cluster
        return out;
    }

    /** Refuses counts out of range and outputs that cannot be written; the animation export asked for, or null. */
    private RunExport validate(EvaluateSpec run) {
        checkRange("--loops", run.loops(), 0);
        checkRange("--episodes", run.episodes(), 1);
        checkRange("--tests", run.tests(), 1);
        if (run.copies() != null && (run.copies() < 2 || run.copies() > 1000)) {
            throw new IllegalArgumentException("--copies must be in [2, 1000], got " + run.copies());
        }
        if (run.copies() != null && csv != null) {
            throw new IllegalArgumentException("--csv goes without --copies (a sensitivity run writes its figures with --json)");
        }
        if (!(run.nudge() > 0 && run.nudge() <= 1)) {
            throw new IllegalArgumentException("--nudge must be in (0, 1] m/s, got " + run.nudge());
        }
        cluster.validate();
        if (cluster.remote() && (workers != null || export != null)) {
            throw new IllegalArgumentException((workers != null ? "--workers" : "--export") + " goes without --master: "
                    + (workers != null ? "the cluster's cores run the episodes" : "an animation is of one episode, run here"));
        }
        if (workers == null && !cluster.remote()) {
            workers = LocalRollouts.localCores();
        }
        if (workers != null && (workers < 1 || workers > 256)) {
            throw new IllegalArgumentException("--workers must be in [1, 256], got " + workers);
        }
        if (plot == null && json != null) {
            String name = json.getFileName().toString();
            plot = json.resolveSibling((name.endsWith(".json") ? name.substring(0, name.length() - 5) : name) + ".png");
        }
        if (specFile != null) { // the policies of a recorded run are named by no option
            run.policies().forEach((role, file) -> OutputPaths.input(file, "the " + role.replace('_', ' ') + " recorded in --spec "
                    + specFile));
        }
        new OutputPaths().heldFile("--json", json).file("--json", json == null ? null : EvaluationJournals.file(json)).file("--csv", csv)
                .file("--plot", plot).check();
        return RunExport.to(export);
    }

    private static void checkRange(String option, int value, int low) {
        if (value < low || value > 100000) {
            throw new IllegalArgumentException(option + " must be in [" + low + ", 100000], got " + value);
        }
    }
}
