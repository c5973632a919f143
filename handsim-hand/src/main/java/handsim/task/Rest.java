package handsim.task;

import handsim.control.Observation;
import handsim.math.Vec3;
import handsim.sim.ObjectSpec;
import java.util.Arrays;
import java.util.Locale;
import java.util.function.Predicate;

/**
 * How a long object lay in the hand when the catch before a throw was judged: raised or flat,
 * across or askew. The flip task's report counts throws by it, and a rest policy throws from one.
 */
public enum Rest {
    RAISED_ACROSS, RAISED_ASKEW, FLAT_ACROSS, FLAT_ASKEW;

    /**
     * A rest less than this far out of the palm's plane lies flat: the long object lies on the
     * palm instead of propped up on the curled fingers (docs/experiments.md, rests).
     */
    public static final double FLAT_TILT = Math.toRadians(10);
    /**
     * A rest this far or more from across the palm lies askew: the closing fingers turn a long
     * object met a few degrees off the palm's planned axis back by about 10 degrees, and
     * the throws that fail after the first mostly start from rests turned 5 degrees or more
     * (docs/experiments.md, rests).
     */
    public static final double ASKEW_HEADING = Math.toRadians(5);

    /** The rest of a catch's {@link LoopRecord#catchTilt} and {@link LoopRecord#catchHeading}. */
    public static Rest of(double tilt, double heading) {
        boolean flat = tilt < FLAT_TILT, askew = heading >= ASKEW_HEADING;
        return flat ? (askew ? FLAT_ASKEW : FLAT_ACROSS) : (askew ? RAISED_ASKEW : RAISED_ACROSS);
    }

    /**
     * The rest of an object with long axis {@code longAxis} (body frame, unit) as {@code at}
     * sees it: at a throw's decision, made in the tick the catch is judged, the rest that
     * catch's {@link LoopRecord} records.
     */
    public static Rest at(Observation at, Vec3 longAxis) {
        LyingPose pose = LyingPose.of(at.palm(), at.object().orientation().rotate(longAxis));
        return of(pose.tilt(), pose.heading());
    }

    /** Which decisions find {@code object} resting this way ({@link #at}); refused for an object without a long axis. */
    public Predicate<Observation> decisionsOf(ObjectSpec object) {
        Vec3 axis = object.longAxis().orElseThrow(() -> new IllegalArgumentException("a " + object.name()
                + " has no long axis to rest along"));
        return observation -> at(observation, axis) == this;
    }

    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The rest named by {@link #label}; an unknown name is refused with the names there are. */
    public static Rest ofLabel(String label) {
        for (Rest r : values()) {
            if (r.label().equals(label)) {
                return r;
            }
        }
        throw new IllegalArgumentException("no rest \"" + label + "\" (one of " + Arrays.stream(values()).map(Rest::label).toList() + ")");
    }
}
