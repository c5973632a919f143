package handsim.train;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.ConfigException;
import handsim.config.Home;
import handsim.config.Json;
import handsim.control.ThrowParameters;
import handsim.control.ThrowPolicy;
import handsim.control.ThrowSpace;
import handsim.learn.Policy;
import handsim.report.Outputs;
import handsim.sim.ObjectSpec;
import handsim.task.Rest;
import handsim.task.StateVector;
import handsim.task.ThrowTask;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A trained throw policy on disk ({@code models/policies/*.json}): the plain-Java actor with its
 * observation statistics, and what it was trained for, so that it is never used for something
 * else: the task, the object, the encoding and length of its state, the box of throw parameters
 * its [-1, 1] actions map onto, and where it came from (run, config, seed, commit).
 *
 * @param state the state encoding it reads ({@code "state"} in the file, {@code paper} when absent)
 * @param provenance free-form facts about the training run that made it
 */
public record ThrowPolicyFile(String task, String object, StateVector.Encoding state, ThrowSpace space, Policy policy,
        ObjectNode provenance) {

    public static final String FORMAT = "handsim-throw-policy";

    public ThrowPolicyFile {
        if (policy.actionSize() != ThrowParameters.SIZE) {
            throw new IllegalArgumentException("a throw policy has " + ThrowParameters.SIZE + " outputs, this one " + policy.actionSize());
        }
    }

    /** Where handsim ships the policy of {@code task} with {@code object}: {@code models/policies/<task>-<object>.json}. */
    public static Path shipped(String task, String object) {
        return Home.resolve("models/policies/" + task + "-" + object + ".json");
    }

    /**
     * Where handsim ships the opening policy of {@code task} with {@code object}, the one that makes
     * each episode's first throw (from the object caught out of the launch) when it exists: {@code
     * models/policies/<task>-<object>-opening.json}; null when none ships.
     */
    public static Path shippedOpening(String task, String object) {
        Path file = Home.resolve("models/policies/" + task + "-" + object + "-opening.json");
        return Files.isRegularFile(file) ? file : null;
    }

    /**
     * Where handsim ships the rest policy of {@code task} with {@code object}, the one that makes
     * the throws from one rest of the object in the hand ({@link #restServed}): {@code
     * models/policies/<task>-<object>-rest.json}; null when none ships.
     */
    public static Path shippedRest(String task, String object) {
        Path file = Home.resolve("models/policies/" + task + "-" + object + "-rest.json");
        return Files.isRegularFile(file) ? file : null;
    }

    /**
     * The controller's throw policy for {@code task}: the policy of {@code file}; when {@code
     * opening} is not null, that file's policy for each episode's first throw
     * ({@link ThrowPolicy#withOpening}); when {@code rest} is not null, that file's policy for the
     * later throws made from the rest it serves ({@link #restServed}). Fails as {@link #forTask}
     * does for any of the files.
     */
    public static ThrowPolicy throwPolicy(Path file, Path opening, Path rest, ThrowTask task, ObjectSpec object, StateVector.Hand hand) {
        return throwPolicy(load(file), opening == null ? null : loadOpening(opening), opening,
                rest == null ? null : loadAs("rest", rest), rest, task, object, hand);
    }

    /** {@link #load} of an opening policy's file, an error in it named as the opening policy's. */
    public static ThrowPolicyFile loadOpening(Path file) {
        return loadAs("opening", file);
    }

    /** {@link #load} of a rest policy's file ({@link #restServed}), an error in it named as the rest policy's. */
    public static ThrowPolicyFile loadRest(Path file) {
        ThrowPolicyFile f = loadAs("rest", file);
        try {
            f.restServed();
        } catch (IllegalArgumentException e) {
            throw new ConfigException("the rest policy " + file + ": " + e.getMessage(), e);
        }
        return f;
    }

    private static ThrowPolicyFile loadAs(String role, Path file) {
        try {
            return load(file);
        } catch (ConfigException e) {
            throw new ConfigException("the " + role + " policy " + e.getMessage(), e);
        }
    }

    /**
     * The rest of a long object in the hand this policy was trained to throw from: the {@code
     * learnerThrows.rest} of its DAgger run's config ({@link DaggerRunConfig.LearnerThrows});
     * fails when it was trained for every throw.
     */
    public Rest restServed() {
        var rest = provenance.path("config").path("learnerThrows").path("rest");
        if (!rest.isTextual()) {
            throw new IllegalArgumentException("it was trained for every throw, not one rest (its provenance has no config.learnerThrows.rest)");
        }
        return Rest.ofLabel(rest.asText());
    }

    /**
     * {@link #throwPolicy(Path, Path, Path, ThrowTask, ObjectSpec, StateVector.Hand)} from files
     * already loaded ({@code opening}, {@code rest} null for none), for callers that make a policy
     * per worker; {@code openingFile} and {@code restFile} name those files in an error.
     */
    public static ThrowPolicy throwPolicy(ThrowPolicyFile policy, ThrowPolicyFile opening, Path openingFile, ThrowPolicyFile rest,
            Path restFile, ThrowTask task, ObjectSpec object, StateVector.Hand hand) {
        ThrowPolicy usual = policy.forTask(task, object, hand);
        try {
            usual = opening == null ? usual : ThrowPolicy.withOpening(opening.forTask(task, object, hand), usual);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("the opening policy " + openingFile + ": " + e.getMessage(), e);
        }
        if (rest == null) {
            return usual;
        }
        try {
            return usual.withSpecialAt(rest.restServed().decisionsOf(object), rest.forTask(task, object, hand));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("the rest policy " + restFile + ": " + e.getMessage(), e);
        }
    }

    public static ThrowPolicyFile load(Path file) {
        Json j = Json.load(file);
        if (!FORMAT.equals(j.string("format"))) {
            throw j.fieldError("format", "expected \"" + FORMAT + "\", got \"" + j.string("format") + "\"");
        }
        Json s = j.get("throwSpace");
        ThrowSpace space;
        try {
            space = new ThrowSpace(s.numbers("low", ThrowParameters.SIZE), s.numbers("high", ThrowParameters.SIZE));
        } catch (IllegalArgumentException e) {
            throw s.error(e.getMessage());
        }
        s.requireNoUnknownFields();
        StateVector.Encoding state = StateVector.Encoding.read(j);
        Json provenance = j.get("provenance");
        if (!provenance.node().isObject()) {
            throw provenance.error("expected an object (facts about the run that trained it)");
        }
        ThrowPolicyFile f;
        try {
            f = new ThrowPolicyFile(j.string("task"), j.string("object"), state, space, Policy.parse(j.get("policy")),
                    (ObjectNode) provenance.node());
        } catch (IllegalArgumentException e) {
            throw j.fieldError("policy", e.getMessage());
        }
        j.requireNoUnknownFields();
        return f;
    }

    public void save(Path file) throws IOException {
        ObjectNode root = Json.mapper().createObjectNode();
        root.put("format", FORMAT);
        root.put("task", task);
        root.put("object", object);
        root.put("state", state.label());
        ObjectNode s = root.putObject("throwSpace");
        s.set("low", Json.array(space.low()));
        s.set("high", Json.array(space.high()));
        root.set("provenance", provenance);
        root.set("policy", policy.toJson());
        Outputs.writeJson(file, root);
    }

    /**
     * The policy of {@code file} to start a learner on {@code envs} with ({@code --init-actor});
     * refused, naming the file, when it was trained for another task, object, state or throw box.
     */
    public static ThrowPolicyFile initActor(Path file, ThrowEnvFactory envs) {
        ThrowPolicyFile f = load(file);
        String mismatch = f.mismatch(envs);
        if (mismatch != null) {
            throw new IllegalArgumentException("--init-actor " + file + " " + mismatch);
        }
        return f;
    }

    /**
     * Why this policy cannot start a learner on {@code envs} (another task, object, state encoding
     * or throw box), or null when it can.
     */
    private String mismatch(ThrowEnvFactory envs) {
        return !task.equals(envs.task()) || !object.equals(envs.object().name())
                ? "was trained for the " + task + " task with a " + object + ", this run is the " + envs.task()
                        + " task with a " + envs.object().name()
                : state != envs.state().encoding() ? "reads the " + state.label() + " state, this run gives the "
                        + envs.state().encoding().label() + " state (run.state)"
                : !space.sameBox(envs.space()) ? "throws in " + space + ", this run's task in " + envs.space() : null;
    }

    /**
     * The policy as the controller's throw policy for {@code task}; fails with a message naming
     * the mismatch if it was trained for another task, object or state.
     */
    public LearnedThrowPolicy forTask(ThrowTask task, ObjectSpec object) {
        return forTask(task, object, null);
    }

    /**
     * {@link #forTask(ThrowTask, ObjectSpec)} in a hand of the given sizes (needed by a policy
     * that reads the extended state, {@link StateVector.Encoding#handSized}; else may be null).
     */
    public LearnedThrowPolicy forTask(ThrowTask task, ObjectSpec object, StateVector.Hand hand) {
        if (!this.task.equals(task.name()) || !this.object.equals(object.name())) {
            throw new IllegalArgumentException("this policy was trained for the " + this.task + " task with a " + this.object
                    + ", not the " + task.name() + " task with a " + object.name());
        }
        StateVector encoder = new StateVector(state, object.longAxis(), hand);
        int size = encoder.size(task.goalSize());
        if (policy.observationSize() != size) {
            throw new IllegalArgumentException("this policy reads " + policy.observationSize() + " state entries, the "
                    + task.name() + " task gives " + size + " (" + state.label() + " state)");
        }
        return new LearnedThrowPolicy(policy, space, task, encoder);
    }
}
