package handsim.app;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.ConfigSet;
import handsim.config.Home;
import handsim.config.Json;
import handsim.config.ReadLog;
import handsim.control.ThrowPolicy;
import handsim.evaluation.CatchEvaluation;
import handsim.evaluation.EvaluationRequest;
import handsim.evaluation.EvaluationSetup;
import handsim.spec.RunConfigs;
import handsim.task.StateVector;
import handsim.task.ThrowTask;
import handsim.taskdef.TaskDefinition;
import handsim.taskdef.TaskDefinitions;
import handsim.train.ThrowPolicyFile;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Function;

/**
 * An {@code evaluate} run, resolved: every option that makes its episodes what they are, the
 * documents of its configuration as read (the task's file with {@code --task-set} applied), the
 * goals read, and the policy files it throws with (by path and SHA-256). Its JSON ({@link #toJson})
 * is the run's record {@code spec}; {@code evaluate --spec FILE} repeats a run from it alone (the
 * policies are found at their paths and must have the bytes recorded).
 *
 * @param loops height and sensitivity: throws per episode after the first catch; flip: the most loops in a row
 * @param goals the goals file read ({@code --goals}), or null
 * @param taskSet the fields of the task's file changed (applied in {@code configs}; recorded to be read)
 * @param policies the learned controller's policy files by role (policy, opening_policy, rest_policy; absent: none)
 */
record EvaluateSpec(String task, String controller, String object, boolean plan, long seed, int loops, int episodes, int tests,
        Double throwHeight, Json goals, Integer copies, double nudge, Map<String, String> taskSet, Map<String, Path> policies,
        RunConfigs configs) {

    /**
     * The spec of a run given by its options; the defaults come from the task's and the evaluation's
     * configs; {@code who}'s --stepper (null: configs/sim.json's) overrides the physics' {@code solver.stepper}.
     */
    static EvaluateSpec of(ControllerOptions who, String object, long seed, Integer loops, int episodes, int tests, Double throwHeight,
            Path goals, Integer copies, double nudge) {
        Map<String, String> taskSet = who.taskSetFields();
        RunConfigs configs = RunConfigs.ofProject(who.task(), taskSet, who.stepper);
        String task = who.task();
        int resolvedLoops = loops != null ? loops : copies != null ? configs.evaluation().sensitivityThrows()
                : configs.task(task).defaultEvaluationLoops();
        Map<String, Path> policies = new LinkedHashMap<>();
        if (who.controller().equals("learned")) {
            policies.put("policy", who.policyFile(object));
        }
        putIfGiven(policies, "opening_policy", who.openingFile(object));
        putIfGiven(policies, "rest_policy", who.restFile(object));
        if (goals != null && !Files.isRegularFile(goals)) {
            throw new IllegalArgumentException("--goals: no file " + goals);
        }
        return new EvaluateSpec(task, who.controller(), object, who.plan, seed, resolvedLoops, episodes, tests, throwHeight,
                goals != null ? Json.load(goals) : null, copies, nudge, taskSet, policies, configs);
    }

    private static void putIfGiven(Map<String, Path> policies, String role, Path file) {
        if (file != null) {
            policies.put(role, file);
        }
    }

    /** The spec recorded in {@code file}: an evaluate JSON (its {@code spec}) or a spec alone. */
    static EvaluateSpec read(Path file) {
        Json root = Json.load(file);
        return of(root.has("spec") ? root.get("spec") : root);
    }

    /** The spec recorded as {@code j} ({@link #toJson}). */
    static EvaluateSpec of(Json j) {
        Map<String, String> taskSet = new LinkedHashMap<>();
        if (j.has("task_set")) {
            j.get("task_set").fieldNames().forEach(k -> taskSet.put(k, j.get("task_set").node().get(k).toString()));
        }
        Map<String, Path> policies = new LinkedHashMap<>();
        if (j.has("policies")) {
            Json p = j.get("policies");
            for (String role : p.fieldNames()) {
                policies.put(role, recordedPolicy(p.get(role)));
            }
        }
        EvaluateSpec s = new EvaluateSpec(j.string("task"), j.string("controller"), j.string("object"), j.bool("plan", false),
                j.node().get("seed").asLong(), j.integer("loops", 0, 100000), j.integer("episodes", 1, 100000),
                j.integer("tests", 1, 100000), j.has("throw_height") ? j.number("throw_height", 0, 100) : null,
                j.has("goals") ? j.get("goals") : null, j.has("copies") ? j.integer("copies", 2, 1000) : null,
                j.has("nudge") ? j.number("nudge", 0, 1) : 1e-9, taskSet, policies, new RunConfigs(ConfigSet.replaying(j.get("configs"))));
        TaskDefinitions.checkName(s.task);
        return s;
    }

    /** A policy file of the record: it must still exist with the bytes it had. */
    private static Path recordedPolicy(Json p) {
        Path file = Path.of(p.string("file"));
        Path resolved = file.isAbsolute() ? file : Home.root().resolve(file);
        String sha;
        try {
            sha = ReadLog.sha256(Files.readAllBytes(resolved));
        } catch (IOException e) {
            throw p.fieldError("file", "cannot read " + resolved + " (" + e.getMessage() + ")");
        }
        if (!sha.equals(p.string("sha256"))) {
            throw p.fieldError("sha256", resolved + " is not the policy the run threw with (its SHA-256 is " + sha + ")");
        }
        return resolved;
    }

    /** The task's definition, as these configs give it. */
    TaskDefinition definition() {
        return configs.task(task);
    }

    /** What the evaluation runs with: this spec's configs and policies, twins from {@link Wiring}; {@code watcher} may be null. */
    EvaluationSetup setup(CatchEvaluation.TickWatcher watcher, PrintStream console) {
        return new EvaluationSetup(configs.controller(), configs.object(object), configs.limits(), configs.launches(), configs.evaluation(),
                throwPolicies(), plan ? configs.planner(object) : null, Wiring::twinSimulator, watcher, null, console);
    }

    EvaluationRequest request(Path csv, Path plot, boolean exported) {
        return new EvaluationRequest(task, object, controller, plan, seed, loops, episodes, tests, throwHeight, goals, copies, nudge,
                csv, plot, exported);
    }

    /** How each worker's task gets its throw policy: the task's nominal throw, or the learned policy (and its opening and rest). */
    Function<ThrowTask, ThrowPolicy> throwPolicies() {
        Path file = policies.get("policy");
        if (file == null) {
            return t -> obs -> t.nominalThrow();
        }
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException("no policy file " + file + " for the " + task + " task with a " + object
                    + ": train one (scripts/handsim train) and give it with --policy");
        }
        Path opening = policies.get("opening_policy");
        Path rest = policies.get("rest_policy");
        StateVector.Hand hand = StateVector.Hand.of(configs.model());
        // each file read once, each worker's task given its own policy
        ThrowPolicyFile loaded = ThrowPolicyFile.load(file);
        ThrowPolicyFile loadedOpening = opening == null ? null : ThrowPolicyFile.loadOpening(opening);
        ThrowPolicyFile loadedRest = rest == null ? null : ThrowPolicyFile.loadRest(rest);
        var spec = configs.object(object);
        // a policy for another task or object fails here
        ThrowPolicyFile.throwPolicy(loaded, loadedOpening, opening, loadedRest, rest, definition().newTask(object), spec, hand);
        return t -> ThrowPolicyFile.throwPolicy(loaded, loadedOpening, opening, loadedRest, rest, t, spec, hand);
    }

    /**
     * What the controller of this run is made of, each part with where it comes from: the throws
     * (the task's nominal throw, hand-designed, or a policy and how it was learned, read from its
     * provenance), the opening and rest policies, the parts the task adds by hand, and the
     * twin-world planner when it chooses the throws.
     */
    ObjectNode controllerParts() {
        ObjectNode o = JsonNodeFactory.instance.objectNode();
        o.put("throws", policies.containsKey("policy") ? learned(policies.get("policy")) : "hand-designed: the task's nominal throw");
        if (policies.containsKey("opening_policy")) {
            o.put("opening_throws", learned(policies.get("opening_policy")));
        }
        if (policies.containsKey("rest_policy")) {
            o.put("rest_throws", learned(policies.get("rest_policy")));
        }
        definition().handDesignedParts(object).forEach(o.putArray("hand_designed")::add);
        if (plan) {
            o.put("planner", "the twin-world planner chooses every throw, knowing the future exactly: planner-assisted");
        }
        return o;
    }

    /** How the policy of {@code file} was learned, from its provenance: the command or the run folder that made it. */
    private static String learned(Path file) {
        var provenance = ThrowPolicyFile.load(file).provenance();
        String made = provenance.path("command").asText("") + " " + provenance.path("run").asText("");
        String how = made.contains("dagger") ? "imitation of the twin-world planner (DAgger): distilled from the planner"
                : made.contains("warmstart") ? "regression on CMA-ES throws (the warm start)"
                : made.contains("handsim train") || provenance.has("decisions") ? "DDPG, the paper's method"
                : "a method its file does not record";
        return "learned by " + how + " (" + file.getFileName() + ")";
    }

    /** The fields of the task's file changed, with their values as JSON. */
    ObjectNode toTaskSetJson() {
        ObjectNode set = JsonNodeFactory.instance.objectNode();
        taskSet.forEach((k, v) -> set.set(k, Json.parse("task_set." + k, v).node()));
        return set;
    }

    /** The record: the options, the goals and the policies (path, SHA-256), and every configuration document read so far. */
    ObjectNode toJson() throws IOException {
        ObjectNode o = JsonNodeFactory.instance.objectNode();
        o.put("task", task).put("controller", controller).put("object", object).put("plan", plan).put("seed", seed)
                .put("loops", loops).put("episodes", episodes).put("tests", tests);
        if (throwHeight != null) {
            o.put("throw_height", throwHeight);
        }
        if (goals != null) {
            o.set("goals", goals.node());
        }
        if (copies != null) {
            o.put("copies", copies).put("nudge", nudge);
        }
        if (!taskSet.isEmpty()) {
            o.set("task_set", toTaskSetJson());
        }
        ObjectNode p = o.putObject("policies");
        for (var e : policies.entrySet()) {
            Path f = e.getValue().toAbsolutePath().normalize();
            p.putObject(e.getKey()).put("file", f.startsWith(Home.root()) ? Home.root().relativize(f).toString() : f.toString())
                    .put("sha256", ReadLog.sha256(Files.readAllBytes(f)));
        }
        o.set("configs", configs.files().toJson());
        return o;
    }
}
