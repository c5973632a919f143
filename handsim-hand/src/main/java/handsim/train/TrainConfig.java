package handsim.train;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.learn.LearnerConfig;
import handsim.sim.SimConfig;
import handsim.task.StateVector;
import handsim.taskdef.TaskDefinitions;
import java.nio.file.Path;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A training run's configuration ({@code configs/train/*.json}): the {@code run} section says
 * what is trained, every other section is the learner's ({@link LearnerConfig}, documented in
 * {@code configs/train/README.md}).
 *
 * @param learner DDPG, exploration, training budget, pretraining and CMA-ES settings, and the root seed
 */
public record TrainConfig(Run run, LearnerConfig learner) {

    /**
     * What to train and how to run it.
     *
     * @param name the run's name (part of the run folder's name)
     * @param task {@code height}, {@code box} or {@code flip} (configs/tasks)
     * @param object the thrown object (configs/objects)
     * @param workers episodes played at once (threads, each with its own simulator)
     * @param firstCatchAttempts launches tried per episode before the object is caught
     * @param divergedReward reward of a throw whose simulation diverged (an episode end)
     * @param progressSeconds seconds between progress lines
     * @param state how the learner's state is written ({@code paper} when absent: the runs made
     *     before there was a choice)
     * @param spinShaping a training-only reward term for the release spin of flips ({@link
     *     SpinShaping}; {@link SpinShaping#NONE}, the paper's reward, when absent)
     * @param endAtFailedThrow a training episode ends at the first throw that is not a success of
     *     the task, as an evaluation episode does (false when absent: only a drop ends it)
     * @param taskSet fields of the task's file (configs/tasks/TASK.json) changed for this run, as
     *     {@code evaluate --task-set} changes them ({@link handsim.config.Json#withOverrides}: dotted
     *     paths, JSON values, {@code null} leaves an optional field out); empty: the task as its
     *     file says
     * @param stepper the constrained step the run's physics takes ({@code handsim} or {@code ode4j}),
     *     overriding configs/sim.json's {@code solver.stepper}; null when absent: the file's
     */
    public record Run(String name, String task, String object, int workers, int firstCatchAttempts, double divergedReward,
            double progressSeconds, StateVector.Encoding state, SpinShaping spinShaping,
            boolean endAtFailedThrow, Map<String, String> taskSet, String stepper) {

        public Run {
            taskSet = Collections.unmodifiableMap(new LinkedHashMap<>(taskSet));
        }

        static Run parse(Json j) {
            j.allow("comment");
            Run r = new Run(j.string("name"), j.string("task"), j.string("object"), j.integer("workers", 1, 256),
                    j.integer("firstCatchAttempts", 1, 100), j.number("divergedReward", -1e6, 0),
                    j.positive("progressSeconds"), StateVector.Encoding.read(j), SpinShaping.read(j),
                    j.bool("endAtFailedThrow", false), taskSet(j), j.has("stepper") ? j.choice("stepper", SimConfig.Stepper.labels()) : null);
            if (!r.name.matches("[A-Za-z0-9._-]+")) {
                throw j.fieldError("name", "letters, digits, '.', '_' and '-' only (it names a folder), got \"" + r.name + "\"");
            }
            j.requireNoUnknownFields();
            return r;
        }

        /**
         * The run's {@code taskSet}. A run section without one, as run folders hold that name the flip
         * task's catch ({@code catch}) and arm rest ({@code armRest}) in the run itself, reads as the
         * fields of the task's file those stand for: its catch replaced by {@code catch}, and the arm
         * rest left out unless {@code armRest} is true.
         */
        private static Map<String, String> taskSet(Json j) {
            Map<String, String> fields = new LinkedHashMap<>();
            if (j.has("taskSet")) {
                Json set = j.get("taskSet");
                for (String key : set.fieldNames()) {
                    fields.put(key, set.node().get(key).toString());
                }
                return fields;
            }
            return TaskDefinitions.runFields(j.string("task"), j.string("object"), j.bool("armRest", false),
                    j.has("catch") ? j.get("catch").node().toString() : null);
        }
    }

    public static TrainConfig load(Path file) {
        return parse(Json.load(file));
    }

    /** Parses a whole file: {@code run} plus the learner's sections. */
    public static TrainConfig parse(Json j) {
        Run run = Run.parse(j.get("run"));
        ObjectNode rest = ((ObjectNode) j.node()).deepCopy();
        rest.remove("run");
        return new TrainConfig(run, LearnerConfig.parse(Json.of(j.source(), rest)));
    }

    /** This configuration in the file's format ({@code parse(toJson())} gives it back). */
    public ObjectNode toJson() {
        ObjectNode root = Json.mapper().createObjectNode();
        ObjectNode runNode = Json.mapper().valueToTree(run);
        runNode.put("state", run.state().label());
        if (run.spinShaping().equals(SpinShaping.NONE)) {
            runNode.remove("spinShaping");
        }
        if (!run.endAtFailedThrow()) {
            runNode.remove("endAtFailedThrow");
        }
        if (run.stepper() == null) {
            runNode.remove("stepper");
        }
        ObjectNode taskSet = runNode.putObject("taskSet");
        run.taskSet().forEach((key, value) -> taskSet.set(key, Json.parse("taskSet." + key, value).node()));
        root.set("run", runNode);
        root.setAll(learner.toJson());
        return root;
    }
}
