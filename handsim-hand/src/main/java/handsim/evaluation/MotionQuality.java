package handsim.evaluation;

import com.fasterxml.jackson.databind.node.ObjectNode;
import handsim.task.LoopRecord;
import java.util.List;
import java.util.Locale;

/**
 * How natural the motion of some loops was (paper sec. 4.1): the largest joint-limit excess
 * (rad), the deepest hand-object penetration (m) and the peak ratio of a joint's torque to its
 * human limit. Every task's summary reports it over all its loops, under the same keys.
 */
public record MotionQuality(double maxLimitExcess, double maxPenetration, double peakTorqueRatio) {

    /** No loops: nothing exceeded. */
    public static final MotionQuality NONE = new MotionQuality(0, 0, 0);

    /** The figures over {@code loops}, the throw-in included. */
    public static MotionQuality of(List<LoopRecord> loops) {
        return new MotionQuality(loops.stream().mapToDouble(LoopRecord::maxLimitExcess).max().orElse(0),
                loops.stream().mapToDouble(LoopRecord::maxPenetration).max().orElse(0),
                loops.stream().mapToDouble(LoopRecord::peakTorqueRatio).max().orElse(0));
    }

    /** The worse of each figure of this and {@code other} (NaN, a figure not recorded, stays NaN). */
    public MotionQuality max(MotionQuality other) {
        return new MotionQuality(Math.max(maxLimitExcess, other.maxLimitExcess), Math.max(maxPenetration, other.maxPenetration),
                Math.max(peakTorqueRatio, other.peakTorqueRatio));
    }

    /** Puts {@code max_limit_excess_deg}, {@code max_penetration_mm} and {@code peak_torque_ratio} into a summary (null when not recorded). */
    public void putInto(ObjectNode out) {
        TaskEvaluation.putFinite(out, "max_limit_excess_deg", Math.toDegrees(maxLimitExcess));
        TaskEvaluation.putFinite(out, "max_penetration_mm", 1e3 * maxPenetration);
        TaskEvaluation.putFinite(out, "peak_torque_ratio", peakTorqueRatio);
    }

    /** The figures in a summary line. */
    public String line() {
        return String.format(Locale.ROOT, "max limit excess %.2f deg, max penetration %.1f mm, peak torque ratio %.2f",
                Math.toDegrees(maxLimitExcess), 1e3 * maxPenetration, peakTorqueRatio);
    }
}
