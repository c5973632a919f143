package handsim.train;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.config.Json;
import handsim.control.CatchStyle;
import handsim.learn.LearnerConfig;
import handsim.task.StateVector;
import java.nio.file.Path;

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
     * @param catchAfterThrow flip task only: how the catches after the hand's throws meet the
     *     object while training, instead of as the task says ({@code catch}; null when absent: the
     *     task's catch)
     * @param armRest flip task only: the arm's redundancy is drawn toward the object's arm rest
     *     while training, as the task says ({@code armRest} true); false, or absent, leaves it to the
     *     IK, as the shipped can policies and every run folder without the field were trained
     */
    public record Run(String name, String task, String object, int workers, int firstCatchAttempts, double divergedReward,
            double progressSeconds, StateVector.Encoding state, SpinShaping spinShaping,
            boolean endAtFailedThrow, CatchStyle catchAfterThrow, boolean armRest) {

        static Run parse(Json j) {
            j.allow("comment");
            Run r = new Run(j.string("name"), j.string("task"), j.string("object"), j.integer("workers", 1, 256),
                    j.integer("firstCatchAttempts", 1, 100), j.number("divergedReward", -1e6, 0),
                    j.positive("progressSeconds"), StateVector.Encoding.read(j), SpinShaping.read(j),
                    j.bool("endAtFailedThrow", false), j.has("catch") ? CatchStyle.parse(j.get("catch")) : null,
                    j.bool("armRest", false));
            if (!r.name.matches("[A-Za-z0-9._-]+")) {
                throw j.fieldError("name", "letters, digits, '.', '_' and '-' only (it names a folder), got \"" + r.name + "\"");
            }
            if (r.catchAfterThrow != null && !r.task.equals("flip")) {
                throw j.fieldError("catch", "only the flip task's catches can be set here, and the task is \"" + r.task + "\"");
            }
            if (r.armRest && !r.task.equals("flip")) {
                throw j.fieldError("armRest", "only the flip task has an arm rest, and the task is \"" + r.task + "\"");
            }
            j.requireNoUnknownFields();
            return r;
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
        runNode.remove("catchAfterThrow");
        if (!run.armRest()) {
            runNode.remove("armRest");
        }
        if (run.catchAfterThrow() != null) {
            runNode.set("catch", run.catchAfterThrow().toJson());
        }
        root.set("run", runNode);
        root.setAll(learner.toJson());
        return root;
    }
}
