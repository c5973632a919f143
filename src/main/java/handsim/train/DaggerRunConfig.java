package handsim.train;

import handsim.config.Json;
import handsim.learn.DaggerConfig;
import handsim.evaluation.ThrowTeacher;
import java.nio.file.Path;

/**
 * A DAgger run's configuration ({@code configs/train/flip-dagger.json}; every field in {@code
 * configs/train/README.md}): the {@code run} section says what is trained (as a DDPG run's), the
 * {@code teacher} section how the teacher searches ({@link ThrowTeacher.Config}), the rest is the
 * learner's ({@link DaggerConfig}).
 */
public record DaggerRunConfig(TrainConfig.Run run, ThrowTeacher.Config teacher, DaggerConfig learner) {

    public static DaggerRunConfig load(Path file) {
        return parse(Json.load(file));
    }

    public static DaggerRunConfig parse(Json j) {
        j.allow("comment");
        DaggerRunConfig c = new DaggerRunConfig(TrainConfig.Run.parse(j.get("run")), ThrowTeacher.Config.parse(j.get("teacher")),
                DaggerConfig.parse(j));
        j.requireNoUnknownFields();
        return c;
    }
}
