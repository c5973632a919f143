package handsim.train;

import handsim.config.Json;
import handsim.task.LoopRecord;

/**
 * A training-only reward term for flips, added to eq. (7): {@code weight exp(-((s - target) /
 * width)^2)} for a throw whose object left the hand turning end over end at {@code s} rad/s
 * ({@link LoopRecord#releaseSpin}). Eq. (7) pays only for the outcome, which goes with the
 * release spin (docs/experiments.md: the shipped can policy's throws leaving at 7-9 rad/s were
 * flipped and caught lying in the hand 105 times in 108, at 0-3 rad/s never); this term tells
 * the critic which way a failed throw missed. With weight 0.5, target 8 and width 2 it did not
 * help (docs/experiments.md, "Learner"). Evaluation still counts flip-and-catch loops;
 * {@link #NONE} is the paper's reward.
 *
 * @param weight at most this much is added (0: none)
 * @param target the release spin paid most (rad/s)
 * @param width how far from the target the term falls to 1/e of its weight (rad/s)
 */
public record SpinShaping(double weight, double target, double width) {

    public static final SpinShaping NONE = new SpinShaping(0, 0, 1);

    /** The term for a throw; 0 when the loop has no release spin (loop 0, objects without a long axis). */
    public double bonus(LoopRecord thrown) {
        double s = thrown.releaseSpin();
        if (weight == 0 || !Double.isFinite(s)) {
            return 0;
        }
        double z = (s - target) / width;
        return weight * Math.exp(-z * z);
    }

    /** The optional {@code spinShaping} object of a run section; absent: {@link #NONE}. */
    static SpinShaping read(Json run) {
        if (!run.has("spinShaping")) {
            return NONE;
        }
        Json j = run.get("spinShaping");
        j.allow("comment");
        SpinShaping s = new SpinShaping(j.number("weight", 0, 10), j.number("target", 0, 100), j.positive("width"));
        j.requireNoUnknownFields();
        return s;
    }
}
