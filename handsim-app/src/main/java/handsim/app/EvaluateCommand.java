package handsim.app;

import handsim.sim.Simulator;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Home;
import handsim.control.ThrowPolicy;
import handsim.evaluation.EpisodeJournal;
import handsim.evaluation.EvaluationConfig;
import handsim.evaluation.EvaluationRequest;
import handsim.evaluation.EvaluationSetup;
import handsim.evaluation.GoalsFile;
import handsim.evaluation.TaskEvaluation;
import handsim.report.Outputs;
import handsim.rollout.LocalRollouts;
import handsim.rollout.Rollouts;
import handsim.sim.ObjectSpec;
import handsim.task.FlipTask;
import handsim.task.HeightTask;
import handsim.task.StateVector;
import handsim.task.Tasks;
import handsim.task.ThrowTask;
import handsim.train.ThrowPolicyFile;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.concurrent.Callable;
import java.util.function.Function;
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
                    + "not, and report how far each throw's apex and flight rotation spread across the copies")
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

    @Option(names = "--export", paramLabel = "FILE",
            description = "with --episodes 1 (box: --tests 1): also write the episode's animation (FILE.glb, FILE.gltf or FILE.bvh; see export)")
    Path export;

    @Spec
    CommandSpec spec;

    /** --loops, or the task's default. */
    private int loops;
    private String task;
    private String controller;
    private String object;
    private EvaluationConfig config;
    /** The shipped tasks with --task-set applied. */
    private Tasks tasks;
    private HeightTask.Config height;
    /** The episode's animation export, or null. */
    private RunExport exported;

    @Override
    public Integer call() throws Exception {
        String commit = Provenance.gitCommit(); // the code this run begins with
        task = who.task();
        controller = who.controller();
        object = episodeOptions.object;
        config = EvaluationConfig.load(Home.resolve("configs/evaluation.json"));
        height = HeightTask.Config.parse(who.taskFile("height"));
        loops = loopsOption != null ? loopsOption : copies != null ? config.sensitivityThrows()
                : task.equals("flip") ? FlipTask.Config.parse(who.taskFile("flip")).evaluationLoops() : height.evaluationThrows();
        tasks = who.tasks();
        tasks.create(task, object); // a bad --task-set, or an object the task cannot take, fails here, before any file is written
        validate();
        EpisodeJournal journal = null;
        if (json != null) {
            journal = EpisodeJournal.open(json.resolveSibling(json.getFileName() + ".episodes.jsonl"), signature(), commit);
            StopRecords.evaluation(json, journal, spec.commandLine().getParseResult().originalArgs(), commit);
            if (journal.finished() > 0) {
                System.out.printf("resuming: %d finished episodes read from %s%s%n", journal.finished(), journal.file(),
                        journal.droppedLines() > 0 ? " (" + journal.droppedLines() + " line cut short by a kill dropped)" : "");
            }
        }
        long t0 = System.nanoTime();
        ObjectNode out = JsonNodeFactory.instance.objectNode();
        out.put("task", task);
        out.put("controller", controller);
        out.put("planned", who.plan);
        if (who.policy != null || controller.equals("learned")) {
            out.put("policy", who.policyFile(object).toString());
            Path opening = who.openingFile(object);
            out.put("opening_policy", opening != null ? opening.toString() : null);
            Path rest = who.restFile(object);
            out.put("rest_policy", rest != null ? rest.toString() : null);
        }
        out.put("object", object);
        if (!who.taskSet.isEmpty()) {
            out.set("task_set", taskSet());
        }
        out.put("seed", episodeOptions.seed);
        out.put("workers", workers);
        EvaluationRequest request = new EvaluationRequest(task, object, controller, who.plan, episodeOptions.seed, loops, episodes, tests,
                throwHeight, goals != null && !task.equals("box") ? GoalsFile.heights(goals, height) : null,
                goals != null && task.equals("box") ? GoalsFile.boxes(goals) : null, copies, nudge, csv, plot);
        EvaluationSetup setup = new EvaluationSetup(Wiring.controllerConfig(), Wiring.object(object), tasks,
                Wiring.episodeLimits(), Wiring.launches(), config, throwPolicies(), who.plan ? Wiring.plannerConfig(object) : null,
                Wiring::twinSimulator, exported, journal, System.out);
        try (Rollouts<Simulator> rollouts = Wiring.rollouts(Wiring.model(null), Wiring.simConfig(), workers)) {
            TaskEvaluation.of(request, setup).run(rollouts, out);
        }
        out.put("wall_s", (System.nanoTime() - t0) / 1e9);
        if (exported != null) {
            exported.write("handsim evaluate: " + task + " task, " + object + ", " + request.controllerLabel() + " controller, seed "
                    + episodeOptions.seed);
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
        if (json != null) {
            Outputs.writeJson(json, out);
            System.out.println("wrote " + json);
            journal.delete();
        }
        return 0;
    }

    /**
     * What makes this run's episodes what they are: the options that change a result (--task-set
     * among them; not --workers, --episodes or --tests: more episodes of the same run keep the
     * first ones) and the SHA-256 of every file under configs/ and models/ and of --policy and
     * --goals.
     */
    private ObjectNode signature() throws IOException {
        ObjectNode s = JsonNodeFactory.instance.objectNode();
        s.put("task", task).put("controller", controller).put("plan", who.plan).put("object", object).put("loops", loops)
                .put("seed", episodeOptions.seed);
        Path policy = controller.equals("learned") ? who.policyFile(object) : null;
        s.put("policy", policy != null ? policy.toAbsolutePath().normalize().toString() : null);
        Path opening = who.openingFile(object); // null for the nominal controller
        s.put("opening_policy", opening != null ? opening.toAbsolutePath().normalize().toString() : null);
        Path rest = who.restFile(object); // null for the nominal controller
        if (rest != null) { // absent when none: a run without one keeps the signature it had without the option
            s.put("rest_policy", rest.toAbsolutePath().normalize().toString());
        }
        if (!who.taskSet.isEmpty()) { // absent when none, as rest_policy
            s.set("task_set", taskSet());
        }
        s.put("throw_height", throwHeight);
        s.put("copies", copies);
        s.put("nudge", copies != null ? nudge : null);
        ObjectNode files = s.putObject("files");
        EpisodeJournal.inputHashes(Arrays.asList(policy, opening, rest, goals)).forEach(files::put);
        return s;
    }

    private void validate() {
        who.validate();
        if (loops < 0 || loops > 100000) {
            throw new IllegalArgumentException("--loops must be in [0, 100000], got " + loops);
        }
        if (episodes < 1 || episodes > 100000) {
            throw new IllegalArgumentException("--episodes must be in [1, 100000], got " + episodes);
        }
        if (tests < 1 || tests > 100000) {
            throw new IllegalArgumentException("--tests must be in [1, 100000], got " + tests);
        }
        if (throwHeight != null && !height.allowsGoal(throwHeight)) {
            throw new IllegalArgumentException("--throw-height must be in " + height.goalLimits() + ", got " + throwHeight);
        }
        if (throwHeight != null && (goals != null || task.equals("box"))) {
            throw new IllegalArgumentException("--throw-height goes with the height task and without --goals");
        }
        if (copies != null && (copies < 2 || copies > 1000 || task.equals("box"))) {
            throw new IllegalArgumentException("--copies must be in [2, 1000] and goes with the height or flip task, got " + copies
                    + " with " + task);
        }
        if (copies != null && csv != null) {
            throw new IllegalArgumentException("--csv goes without --copies (a sensitivity run writes its figures with --json)");
        }
        if (who.plan && (!task.equals("flip") || copies != null)) {
            throw new IllegalArgumentException("--plan goes with the flip task and without --copies");
        }
        if (!(nudge > 0 && nudge <= 1)) {
            throw new IllegalArgumentException("--nudge must be in (0, 1] m/s, got " + nudge);
        }
        if (goals != null && !Files.isRegularFile(goals)) {
            throw new IllegalArgumentException("--goals: no file " + goals);
        }
        if (workers == null) {
            workers = LocalRollouts.localCores();
        }
        if (workers < 1 || workers > 256) {
            throw new IllegalArgumentException("--workers must be in [1, 256], got " + workers);
        }
        if (export != null && (episodes != 1 || copies != null || task.equals("box") && tests != 1)) {
            throw new IllegalArgumentException("--export goes with one episode: --episodes 1 (box: --tests 1), without --copies");
        }
        exported = RunExport.to(export);
        if (plot == null && json != null) {
            String name = json.getFileName().toString();
            plot = json.resolveSibling((name.endsWith(".json") ? name.substring(0, name.length() - 5) : name) + ".png");
        }
        new OutputPaths().heldFile("--json", json).file("--json", json == null ? null : json.resolveSibling(json.getFileName()
                + ".episodes.jsonl")).file("--csv", csv).file("--plot", plot).check();
    }

    /** The --task-set fields, in order. */
    private ObjectNode taskSet() {
        ObjectNode o = JsonNodeFactory.instance.objectNode();
        who.taskSetFields().forEach(o::put);
        return o;
    }

    /** How each worker's task gets its throw policy: the task's nominal throw, or the learned policy (and its opening). */
    private Function<ThrowTask, ThrowPolicy> throwPolicies() {
        if (controller.equals("nominal")) {
            return t -> obs -> t.nominalThrow();
        }
        Path file = who.policyFile(object);
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException(who.policy != null ? "--policy: no file " + file
                    : "no shipped policy for the " + task + " task with a " + object + " (" + Home.root().relativize(file)
                            + "): train one (scripts/handsim train) and give it with --policy");
        }
        Path opening = who.openingFile(object); // given: checked to exist by who.validate()
        ObjectSpec spec = Wiring.object(object);
        StateVector.Hand hand = StateVector.Hand.of(Wiring.model(null));
        // each file read once, each worker's task given its own policy
        ThrowPolicyFile loaded = ThrowPolicyFile.load(file);
        ThrowPolicyFile loadedOpening = opening == null ? null : ThrowPolicyFile.loadOpening(opening);
        Path rest = who.restFile(object);
        ThrowPolicyFile loadedRest = rest == null ? null : ThrowPolicyFile.loadRest(rest);
        ThrowPolicyFile.throwPolicy(loaded, loadedOpening, opening, loadedRest, rest, tasks.create(task, object), spec, hand); // a policy for another task or object fails here
        return t -> ThrowPolicyFile.throwPolicy(loaded, loadedOpening, opening, loadedRest, rest, t, spec, hand);
    }
}
