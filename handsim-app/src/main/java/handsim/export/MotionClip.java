package handsim.export;

import handsim.kin.Frame;
import handsim.math.Quat;
import handsim.math.Vec3;
import handsim.model.HandModel;
import handsim.sim.ObjectSpec;
import handsim.sim.WorldSnapshot;
import handsim.task.Goal;
import java.util.List;

/**
 * A recorded run: the model's body frames, the object and the goal at sample times (seconds from
 * the first sample, increasing; a reset of the world does not take the clock back), taken
 * {@code rate} times a simulated second.
 *
 * @param title what was recorded (the animation's name)
 * @param groundHeight the floor's height (m)
 */
public record MotionClip(String title, HandModel model, double rate, double groundHeight, List<Sample> samples) {

    /**
     * The world at one sample time.
     *
     * @param bodies every model body's frame: origin x, y, z then rotation w, x, y, z (7 values a body, world, metres)
     * @param objectSpec the object in the world, or null
     * @param object its frame (centre of mass, rotation; 7 values), or null
     * @param boxes the static boxes
     */
    public record Sample(double time, double[] bodies, ObjectSpec objectSpec, double[] object,
            List<WorldSnapshot.StaticBox> boxes, Goal goal) {

        public Sample {
            boxes = List.copyOf(boxes);
        }

        /** Body {@code b}'s world frame. */
        public Frame body(int b) {
            return frame(bodies, 7 * b);
        }

        /** The object's world frame (its origin the centre of mass), or null when no object is in the world. */
        public Frame objectFrame() {
            return object == null ? null : frame(object, 0);
        }

        static Sample of(double time, WorldSnapshot s, Goal goal) {
            double[] bodies = new double[7 * s.bodies().size()];
            for (int b = 0; b < s.bodies().size(); b++) {
                put(s.bodies().get(b), bodies, 7 * b);
            }
            double[] object = null;
            if (s.object().isPresent() && s.objectSpec().isPresent()) {
                object = new double[7];
                put(new Frame(s.object().get().position(), s.object().get().orientation()), object, 0);
            }
            return new Sample(time, bodies, object == null ? null : s.objectSpec().get(), object, s.boxes(), goal);
        }

        private static void put(Frame f, double[] out, int at) {
            f.origin().into(out, at);
            Quat r = f.rotation();
            out[at + 3] = r.w();
            out[at + 4] = r.x();
            out[at + 5] = r.y();
            out[at + 6] = r.z();
        }

        private static Frame frame(double[] v, int at) {
            return new Frame(new Vec3(v[at], v[at + 1], v[at + 2]), new Quat(v[at + 3], v[at + 4], v[at + 5], v[at + 6]));
        }
    }

    public MotionClip {
        samples = List.copyOf(samples);
        if (samples.isEmpty()) {
            throw new IllegalArgumentException("a clip needs at least one sample");
        }
    }

    /** Seconds from the first sample to the last. */
    public double duration() {
        return samples.get(samples.size() - 1).time();
    }
}
