package handsim.train;

import handsim.config.Home;
import handsim.config.Json;
import handsim.learn.DaggerConfig;
import handsim.planning.ThrowTeacher;
import handsim.task.Rest;
import java.nio.file.Path;

/**
 * A DAgger run's configuration ({@code configs/train/flip-dagger.json}; every field in {@code
 * configs/train/README.md}): the {@code run} section says what is trained (as a DDPG run's), the
 * {@code teacher} section how the teacher searches ({@link ThrowTeacher.Config}), the optional
 * {@code learnerThrows} section which throws the learner makes ({@link LearnerThrows}; absent:
 * all), the rest is the learner's ({@link DaggerConfig}).
 */
public record DaggerRunConfig(TrainConfig.Run run, ThrowTeacher.Config teacher, DaggerConfig learner, LearnerThrows learnerThrows) {

    /**
     * A learner for one rest of a long object in the hand: it throws (and the teacher labels) only
     * the throws after the first made from {@code rest} ({@link Rest}); the others are
     * thrown by the throw policy {@code leadIn} (files as the flip task's learned controller reads
     * them: {@code leadInOpening}, when not null, for each episode's first throw), and episodes are
     * cut off after throw number {@code maxLoops}. The files are named relative to handsim's folder;
     * a run reads them when it starts ({@link DaggerRun#start}, which refuses a missing one) and
     * copies them into its folder.
     */
    public record LearnerThrows(Rest rest, Path leadIn, Path leadInOpening, int maxLoops) {

        static LearnerThrows parse(Json j) {
            j.allow("comment");
            Rest rest;
            try {
                rest = Rest.ofLabel(j.string("rest"));
            } catch (IllegalArgumentException e) {
                throw j.fieldError("rest", e.getMessage());
            }
            LearnerThrows t = new LearnerThrows(rest, Home.resolve(j.string("leadIn")),
                    j.has("leadInOpening") ? Home.resolve(j.string("leadInOpening")) : null, j.integer("maxLoops", 2, 100_000));
            j.requireNoUnknownFields();
            return t;
        }
    }

    public static DaggerRunConfig load(Path file) {
        return parse(Json.load(file));
    }

    public static DaggerRunConfig parse(Json j) {
        j.allow("comment");
        DaggerRunConfig c = new DaggerRunConfig(TrainConfig.Run.parse(j.get("run")), ThrowTeacher.Config.parse(j.get("teacher")),
                DaggerConfig.parse(j), j.has("learnerThrows") ? LearnerThrows.parse(j.get("learnerThrows")) : null);
        j.requireNoUnknownFields();
        return c;
    }
}
